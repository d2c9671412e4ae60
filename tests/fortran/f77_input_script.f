C     SPDX-License-Identifier: MIT
      PROGRAM INSCR
!     Scripted input from Fortran (GKS_INPUT_SCRIPT names
!     f77_input_script.txt): a drastr-like REQUEST STROKE, REQUEST
!     CHOICE and STRING, REQUEST LOCATOR 3, a valuator event through
!     GWAIT/GGTVL, an exhausted script (status NONE at once), the
!     3-D state and default inquiries, and GPREC/GUREC round trips.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER NFAIL, ISTAT, ITNR, NP, ICH, LOSTR, IVW, IERR, LDR, I
      INTEGER IWK, ICL, IDNR, MODE, IESW, IPET, IOL
      INTEGER IA(3), JA(3), LSTR(2), JSTR(2), IL, RL, SL
      REAL XA(10), YA(10), PX, PY, PZ, VAL, RA(2), SA(2), EVOL(6)
      CHARACTER*80 DATREC(4)
      CHARACTER*20 STR
      CHARACTER*8 S2(2), T2(2)
      DATA IA /7, -3, 12345/, RA /0.5, -2.25/
      NFAIL = 0
      CALL GOPKS(6, 0)
      CALL GOPWK(1, 0, GWSPNG)
      CALL GACWK(1)
      CALL GSWN(1, 0.0, 10.0, 0.0, 10.0)
      CALL GSVP(1, 0.0, 1.0, 0.0, 1.0)
      CALL GSVPIP(1, 0, GHIGHR)
      CALL GRQSK(1, 1, 10, ISTAT, ITNR, NP, XA, YA)
      CALL CHKI('GRQSK STAT', ISTAT, GOK, NFAIL)
      CALL CHKI('GRQSK TNR', ITNR, 1, NFAIL)
      CALL CHKI('GRQSK NP', NP, 3, NFAIL)
      CALL CHKR('GRQSK X2', XA(2), 5.0, NFAIL)
      CALL CHKR('GRQSK Y3', YA(3), 2.0, NFAIL)
      CALL GPL(NP, XA, YA)
      CALL GRQCH(1, 1, ISTAT, ICH)
      CALL CHKI('GRQCH', ICH, 3, NFAIL)
      CALL GRQST(1, 1, ISTAT, LOSTR, STR)
      CALL CHKI('GRQST LEN', LOSTR, 13, NFAIL)
      IF (STR .NE. 'SCRIPTED TEXT') NFAIL = NFAIL + 1
      CALL GRQLC3(1, 1, ISTAT, IVW, ITNR, PX, PY, PZ)
      CALL CHKI('GRQLC3 VIEW', IVW, 0, NFAIL)
      CALL CHKR('GRQLC3 X', PX, 2.5, NFAIL)
      CALL CHKR('GRQLC3 Z', PZ, 0.5, NFAIL)
      CALL GSVLM(1, 1, GEVENT, GECHO)
      CALL GWAIT(0.0, IWK, ICL, IDNR)
      CALL CHKI('GWAIT ICL', ICL, GVALUA, NFAIL)
      CALL GGTVL(VAL)
      CALL CHKR('GGTVL', VAL, 0.75, NFAIL)
      CALL GRQLC(1, 1, ISTAT, ITNR, PX, PY)
      CALL CHKI('exhausted', ISTAT, GNONE, NFAIL)
!     3-D initialisation and inquiry with a packed data record
      SL = 2
      LSTR(1) = 3
      LSTR(2) = 8
      S2(1) = 'ONE'
      S2(2) = 'TWO WORD'
      CALL GPREC(3, IA, 2, RA, SL, LSTR, S2, 4, IERR, LDR, DATREC)
      CALL CHKI('GPREC', IERR, 0, NFAIL)
      CALL CHKI('GPREC LDR', LDR, 1, NFAIL)
      EVOL(1) = 0.0
      EVOL(2) = 512.0
      EVOL(3) = 0.0
      EVOL(4) = 512.0
      EVOL(5) = 0.0
      EVOL(6) = 1.0
      CALL GINLC3(1, 2, 0, 1, 5.0, 5.0, 0.25, 3, EVOL, LDR, DATREC)
      DATREC(1) = ' '
      DATREC(2) = ' '
      CALL GQLCS3(1, 2, GSET, 4, IERR, MODE, IESW, IVW, ITNR, PX, PY,
     +   PZ, IPET, EVOL, LDR, DATREC)
      CALL CHKI('GQLCS3', IERR, 0, NFAIL)
      CALL CHKI('GQLCS3 PET', IPET, 3, NFAIL)
      CALL CHKR('GQLCS3 PZ', PZ, 0.25, NFAIL)
      CALL CHKR('GQLCS3 EVOL', EVOL(4), 512.0, NFAIL)
      CALL GUREC(LDR, DATREC, 3, 2, 2, IERR, IL, JA, RL, SA, SL, JSTR,
     +   T2)
      CALL CHKI('GUREC', IERR, 0, NFAIL)
      CALL CHKI('GUREC IL', IL, 3, NFAIL)
      DO 10 I = 1, 3
         CALL CHKI('GUREC IA', JA(I), IA(I), NFAIL)
   10 CONTINUE
      CALL CHKR('GUREC RA', SA(2), -2.25, NFAIL)
      CALL CHKI('GUREC LSTR', JSTR(2), 8, NFAIL)
      IF (T2(2) .NE. 'TWO WORD') NFAIL = NFAIL + 1
      CALL GPREC(3, IA, 2, RA, SL, LSTR, S2, 0, IERR, LDR, DATREC)
      CALL CHKI('GPREC small', IERR, 2001, NFAIL)
      DATREC(1) = 'NOT A RECORD'
      CALL GUREC(1, DATREC, 3, 2, 2, IERR, IL, JA, RL, SA, SL, JSTR, T2)
      CALL CHKI('GUREC bad', IERR, 2003, NFAIL)
      CALL GQDLC3(GWSPNG, 1, 1, 4, IERR, PX, PY, PZ, IOL, IPET, EVOL,
     +   LDR, DATREC)
      CALL CHKI('GQDLC3', IERR, 0, NFAIL)
      CALL CHKI('GQDLC3 OL', IOL, 6, NFAIL)
      CALL CHKR('GQDLC3 EVOL', EVOL(2), 1024.0, NFAIL)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 INPUT SCRIPT PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 INPUT SCRIPT FAIL ', NFAIL
         STOP 1
      END IF
      END
