C     SPDX-License-Identifier: MIT
      PROGRAM TPREC
!     GPREC/GUREC as legacy programs call them (regression tests for
!     xgks's gksdemo.f): the standard's STR(SL) array form; the xgks
!     form with the strings one after another in one CHARACTER; a
!     CHARACTER actual argument for LSTR with SL = 0 (shifted hidden
!     lengths, in f77_gprec_xgks.f), 32 integers in 4 elements of 80;
!     and the packed menu accepted by GINCH (prompt/echo type 3).
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER NFAIL, IERR, LDR, IL, RL, SL, I, IA(32), JA(32)
      INTEGER LSTR(3), JSTR(3), LCH2(2), IMODE, IESW, ISTAT, ICH, IPET
      REAL RA(1), SA(1), EAREA(4)
      CHARACTER*80 DATREC(4), DREC2(2)
      CHARACTER*10 S3(3), T3(3)
      CHARACTER*14 MENU2
      DATA MENU2 /'CONTINUERETURN'/, LCH2 /8, 6/
      NFAIL = 0
!     Standard form: an array of strings, each blank-padded.
      S3(1) = 'ONE'
      S3(2) = 'TWO'
      S3(3) = 'THREE'
      LSTR(1) = 3
      LSTR(2) = 3
      LSTR(3) = 5
      RA(1) = 1.5
      CALL GPREC(0, IA, 1, RA, 3, LSTR, S3, 4, IERR, LDR, DATREC)
      CALL CHKI('GPREC array', IERR, 0, NFAIL)
      CALL GUREC(LDR, DATREC, 1, 1, 3, IERR, IL, JA, RL, SA, SL, JSTR,
     +   T3)
      CALL CHKI('GUREC array', IERR, 0, NFAIL)
      CALL CHKI('GUREC array SL', SL, 3, NFAIL)
      CALL CHKR('GUREC array RA', SA(1), 1.5, NFAIL)
      IF (T3(3) .NE. 'THREE') THEN
         WRITE (*, '(2A)') 'array T3(3): got ', T3(3)
         NFAIL = NFAIL + 1
      END IF
!     xgks form: MENU2 holds 'CONTINUE' and 'RETURN' back to back.
      CALL GPREC(0, IA, 0, RA, 2, LCH2, MENU2, 2, IERR, LDR, DREC2)
      CALL CHKI('GPREC xgks', IERR, 0, NFAIL)
      CALL CHKI('GPREC xgks LDR', LDR, 1, NFAIL)
      CALL GUREC(LDR, DREC2, 1, 1, 3, IERR, IL, JA, RL, SA, SL, JSTR,
     +   T3)
      CALL CHKI('GUREC xgks', IERR, 0, NFAIL)
      CALL CHKI('GUREC xgks SL', SL, 2, NFAIL)
      CALL CHKI('GUREC xgks LSTR', JSTR(2), 6, NFAIL)
      IF (T3(1) .NE. 'CONTINUE' .OR. T3(2) .NE. 'RETURN') THEN
         WRITE (*, '(4A)') 'xgks strings: got ', T3(1), ' ', T3(2)
         NFAIL = NFAIL + 1
      END IF
!     The packed menu as a choice device's data record.
      CALL GOPKS(6, 0)
      CALL GOPWK(1, 0, GWSPNG)
      CALL GINCH(1, 1, GOK, 1, 3, 0.0, 512.0, 0.0, 512.0, LDR, DREC2)
      DREC2(1) = ' '
      CALL GQCHS(1, 1, 2, IERR, IMODE, IESW, ISTAT, ICH, IPET, EAREA,
     +   LDR, DREC2)
      CALL CHKI('GQCHS', IERR, 0, NFAIL)
      CALL CHKI('GQCHS PET', IPET, 3, NFAIL)
      CALL GUREC(LDR, DREC2, 1, 1, 3, IERR, IL, JA, RL, SA, SL, JSTR,
     +   T3)
      CALL CHKI('GUREC GQCHS', IERR, 0, NFAIL)
      IF (T3(2) .NE. 'RETURN') NFAIL = NFAIL + 1
      CALL GCLWK(1)
      CALL GCLKS
!     gksdemo's call: SL = 0, a CHARACTER*1 array for LSTR.
      DO 10 I = 1, 32
         IA(I) = MOD(I, 2) + 1
   10 CONTINUE
      CALL XGKSPR(32, IA, 4, IERR, LDR, DATREC)
      CALL CHKI('GPREC shifted', IERR, 0, NFAIL)
      CALL CHKI('GPREC shifted LDR', LDR, 1, NFAIL)
      CALL GUREC(LDR, DATREC, 32, 1, 3, IERR, IL, JA, RL, SA, SL, JSTR,
     +   T3)
      CALL CHKI('GUREC shifted', IERR, 0, NFAIL)
      CALL CHKI('GUREC shifted IL', IL, 32, NFAIL)
      CALL CHKI('GUREC shifted IA(32)', JA(32), 1, NFAIL)
      CALL CHKI('GUREC shifted IA(31)', JA(31), 2, NFAIL)
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 GPREC PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 GPREC FAIL ', NFAIL
         STOP 1
      END IF
      END
