C     SPDX-License-Identifier: MIT
      PROGRAM INPUT
!     The REQUEST LOCATOR sequence of a legacy interactive program run
!     on a workstation without input devices (category OUTPUT): every
!     input routine links, reports the standard's error to the
!     program's GERHND and leaves status NONE; the inquiries report
!     through ERRIND only.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INCLUDE 'GKSE_PAR'
      INTEGER N, ERRS(40), FCTS(40), FILS(40)
      COMMON /ERRREC/ N, ERRS, FCTS, FILS
      INTEGER NW
      PARAMETER (NW=36)
      INTEGER WERR(NW), WFCT(NW), WFIL(NW)
      INTEGER NFAIL, I, ISTAT, ITNR, ICH, ISG, IPK, LOSTR, NP, IERR
      INTEGER IWK, ICL, IDNR, MODE, IESW, IPET, LDR, IOL, IBUF, IPOS
      INTEGER N1, N2, N3, N4, N5, N6, IFLAG
      REAL PX, PY, VAL, XA(10), YA(10), EAREA(4)
      CHARACTER*80 DATREC(2)
      CHARACTER*20 STR
      DATA WERR /7, 7, 38, 38, 38, 38, 38, 38, 38, 38, 38, 38, 151,
     +   150, 150, 38, 20, 25, 14*38, 4*150/
      DATA WFIL /0, 35*6/
      WFCT(1) = ERQLC
      WFCT(2) = ERQLC
      WFCT(3) = EINLC
      WFCT(4) = ESLCM
      WFCT(5) = ERQLC
      WFCT(6) = EINST
      WFCT(7) = ERQST
      WFCT(8) = ERQSK
      WFCT(9) = ERQCH
      WFCT(10) = ERQVL
      WFCT(11) = ERQPK
      WFCT(12) = ESMLC
      WFCT(13) = EWAIT
      WFCT(14) = EGTLC
      WFCT(15) = EGTST
      WFCT(16) = EFLUSH
      WFCT(17) = ERQLC
      WFCT(18) = ERQLC
      WFCT(19) = EINSK
      WFCT(20) = EINVL
      WFCT(21) = EINCH
      WFCT(22) = EINPK
      WFCT(23) = ESSKM
      WFCT(24) = ESVLM
      WFCT(25) = ESCHM
      WFCT(26) = ESPKM
      WFCT(27) = ESSTM
      WFCT(28) = ESMSK
      WFCT(29) = ESMVL
      WFCT(30) = ESMCH
      WFCT(31) = ESMPK
      WFCT(32) = ESMST
      WFCT(33) = EGTSK
      WFCT(34) = EGTVL
      WFCT(35) = EGTCH
      WFCT(36) = EGTPK
      N = 0
      NFAIL = 0
      DATREC(1) = ' '
      DATREC(2) = ' '
!     state errors: before GOPKS and with no workstation open
      CALL GRQLC(1, 1, ISTAT, ITNR, PX, PY)
      CALL GOPKS(6, -1)
      ISTAT = 99
      CALL GRQLC(1, 1, ISTAT, ITNR, PX, PY)
      CALL CHKI('GRQLC GKOP STAT', ISTAT, GNONE, NFAIL)
      CALL GOPWK(1, 0, GWSNUL)
      CALL GACWK(1)
!     the classic sequence: initialise, request mode, request
      CALL GINLC(1, 1, 0, 0.5, 0.5, 1, 0.0, 1.0, 0.0, 1.0, 1, DATREC)
      CALL GSLCM(1, 1, GREQU, GECHO)
      ISTAT = 99
      ITNR = 99
      PX = 9.0
      CALL GRQLC(1, 1, ISTAT, ITNR, PX, PY)
      CALL CHKI('GRQLC STAT', ISTAT, GNONE, NFAIL)
      CALL CHKI('GRQLC TNR', ITNR, 0, NFAIL)
      CALL CHKR('GRQLC PX', PX, 0.0, NFAIL)
!     the other classes
      CALL GINST(1, 1, 5, 'hello', 1, 0.0, 1.0, 0.0, 1.0, 20, 1, 1,
     +   DATREC)
      STR = 'garbage'
      LOSTR = 7
      CALL GRQST(1, 1, ISTAT, LOSTR, STR)
      CALL CHKI('GRQST LOSTR', LOSTR, 0, NFAIL)
      IF (STR .NE. ' ') THEN
         WRITE (*, '(A)') 'GRQST STR not blank: FAIL'
         NFAIL = NFAIL + 1
      END IF
      NP = 5
      CALL GRQSK(1, 1, 10, ISTAT, ITNR, NP, XA, YA)
      CALL CHKI('GRQSK NP', NP, 0, NFAIL)
      ISTAT = 99
      CALL GRQCH(1, 1, ISTAT, ICH)
      CALL CHKI('GRQCH STAT', ISTAT, GNONE, NFAIL)
      ISTAT = 99
      CALL GRQVL(1, 1, ISTAT, VAL)
      CALL CHKI('GRQVL STAT', ISTAT, GNONE, NFAIL)
      ISTAT = 99
      CALL GRQPK(1, 1, ISTAT, ISG, IPK)
      CALL CHKI('GRQPK STAT', ISTAT, GNONE, NFAIL)
      CALL GSMLC(1, 1, ITNR, PX, PY)
!     event input: an empty queue
      ICL = 99
      CALL GWAIT(0.0, IWK, ICL, IDNR)
      CALL CHKI('GWAIT ICL', ICL, GNCLAS, NFAIL)
      CALL GWAIT(-1.0, IWK, ICL, IDNR)
      CALL GGTLC(ITNR, PX, PY)
      CALL GGTST(LOSTR, STR)
      CALL GFLUSH(1, GLOCAT, 1)
!     workstation identifier errors come first
      CALL GRQLC(-1, 1, ISTAT, ITNR, PX, PY)
      CALL GRQLC(5, 1, ISTAT, ITNR, PX, PY)
!     inquiries: ERRIND only, GERHND is not called
      CALL GQLI(GWSNUL, IERR, N1, N2, N3, N4, N5, N6)
      CALL CHKI('GQLI', IERR, 38, NFAIL)
      CALL GQLI(12345, IERR, N1, N2, N3, N4, N5, N6)
      CALL CHKI('GQLI type', IERR, 23, NFAIL)
      CALL GQLCS(1, 1, GSET, 2, IERR, MODE, IESW, ITNR, PX, PY, IPET,
     +   EAREA, LDR, DATREC)
      CALL CHKI('GQLCS', IERR, 38, NFAIL)
      CALL GQSTS(1, 1, 2, IERR, MODE, IESW, LOSTR, STR, IPET, EAREA,
     +   IBUF, IPOS, LDR, DATREC)
      CALL CHKI('GQSTS', IERR, 38, NFAIL)
      CALL GQDLC(GWSNUL, 1, 1, 2, IERR, PX, PY, IOL, IPET, EAREA, LDR,
     +   DATREC)
      CALL CHKI('GQDLC', IERR, 38, NFAIL)
      CALL GQIQOV(IERR, IWK, ICL, IDNR)
      CALL CHKI('GQIQOV', IERR, 148, NFAIL)
      IFLAG = 99
      CALL GQSIM(IERR, IFLAG)
      CALL CHKI('GQSIM errind', IERR, 0, NFAIL)
      CALL CHKI('GQSIM flag', IFLAG, GNMORE, NFAIL)
!     every other entry point links and reports its error
      XA(1) = 0.1
      YA(1) = 0.2
      CALL GINSK(1, 1, 0, 1, XA, YA, 1, 0.0, 1.0, 0.0, 1.0, 10, 1,
     +   DATREC)
      CALL GINVL(1, 1, 0.5, 1, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 1, DATREC)
      CALL GINCH(1, 1, GOK, 1, 1, 0.0, 1.0, 0.0, 1.0, 1, DATREC)
      CALL GINPK(1, 1, GOK, 1, 1, 1, 0.0, 1.0, 0.0, 1.0, 1, DATREC)
      CALL GSSKM(1, 1, GSAMPL, GNECHO)
      CALL GSVLM(1, 1, GEVENT, GECHO)
      CALL GSCHM(1, 1, GREQU, GECHO)
      CALL GSPKM(1, 1, GREQU, GECHO)
      CALL GSSTM(1, 1, GREQU, GECHO)
      CALL GSMSK(1, 1, 10, ITNR, NP, XA, YA)
      CALL GSMVL(1, 1, VAL)
      CALL GSMCH(1, 1, ISTAT, ICH)
      CALL GSMPK(1, 1, ISTAT, ISG, IPK)
      CALL GSMST(1, 1, LOSTR, STR)
      CALL GGTSK(10, ITNR, NP, XA, YA)
      CALL GGTVL(VAL)
      CALL GGTCH(ISTAT, ICH)
      CALL CHKI('GGTCH STAT', ISTAT, GNONE, NFAIL)
      CALL GGTPK(ISTAT, ISG, IPK)
      CALL GQSKS(1, 1, GSET, 10, 2, IERR, MODE, IESW, ITNR, NP, XA, YA,
     +   IPET, EAREA, IBUF, LDR, DATREC)
      CALL CHKI('GQSKS', IERR, 38, NFAIL)
      CALL GQVLS(1, 1, 2, IERR, MODE, IESW, VAL, IPET, EAREA, PX, PY,
     +   LDR, DATREC)
      CALL CHKI('GQVLS', IERR, 38, NFAIL)
      CALL GQCHS(1, 1, 2, IERR, MODE, IESW, ISTAT, ICH, IPET, EAREA,
     +   LDR, DATREC)
      CALL CHKI('GQCHS', IERR, 38, NFAIL)
      CALL GQPKS(1, 1, GSET, 2, IERR, MODE, IESW, ISTAT, ISG, IPK, IPET,
     +   EAREA, LDR, DATREC)
      CALL CHKI('GQPKS', IERR, 38, NFAIL)
      CALL GQDSK(GWSNUL, 1, 1, 2, IERR, IBUF, IOL, IPET, EAREA, IPOS,
     +   LDR, DATREC)
      CALL CHKI('GQDSK', IERR, 38, NFAIL)
      CALL GQDVL(GWSNUL, 1, 1, 2, IERR, VAL, IOL, IPET, EAREA, PX, PY,
     +   LDR, DATREC)
      CALL CHKI('GQDVL', IERR, 38, NFAIL)
      CALL GQDCH(GWSNUL, 1, 1, 2, IERR, ICH, IOL, IPET, EAREA, LDR,
     +   DATREC)
      CALL CHKI('GQDCH', IERR, 38, NFAIL)
      CALL GQDPK(GWSNUL, 1, 1, 2, IERR, IOL, IPET, EAREA, LDR, DATREC)
      CALL CHKI('GQDPK', IERR, 38, NFAIL)
      CALL GQDST(0, 1, 1, 2, IERR, IBUF, IOL, IPET, EAREA, IPOS, LDR,
     +   DATREC)
      CALL CHKI('GQDST type 0', IERR, 22, NFAIL)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      CALL CHKI('count', N, NW, NFAIL)
      DO 10 I = 1, MIN(N, NW)
         CALL CHKI('ERRNR', ERRS(I), WERR(I), NFAIL)
         CALL CHKI('FCTID', FCTS(I), WFCT(I), NFAIL)
         CALL CHKI('ERRFIL', FILS(I), WFIL(I), NFAIL)
   10 CONTINUE
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 INPUT PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 INPUT FAIL ', NFAIL
         STOP 1
      END IF
      END

      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
!     The application's ERROR HANDLING: records, never logs.
      INTEGER ERRNR, FCTID, ERRFIL
      INTEGER N, ERRS(40), FCTS(40), FILS(40)
      COMMON /ERRREC/ N, ERRS, FCTS, FILS
      IF (N .GE. 40) RETURN
      N = N + 1
      ERRS(N) = ERRNR
      FCTS(N) = FCTID
      FILS(N) = ERRFIL
      END
