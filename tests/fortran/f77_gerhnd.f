C     SPDX-License-Identifier: MIT
      PROGRAM OWNHND
!     A program's own GERHND replaces the library's: it must receive
!     every error with the right ERRNR, FCTID and ERRFIL (unit 0 while
!     GKS is closed).
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INCLUDE 'GKSE_PAR'
      INTEGER N, ERRS(20), FCTS(20), FILS(20)
      COMMON /ERRREC/ N, ERRS, FCTS, FILS
      INTEGER NW
      PARAMETER (NW=14)
      INTEGER NFAIL, I, LODR
      INTEGER WERR(NW), WFCT(NW), WFIL(NW)
      REAL X(2), Y(2)
      CHARACTER*80 IDR(2), ODR(1)
      DATA WERR /8, 23, 25, 2000, 100, 100, 180, 182, 2000, 2000,
     +   2000, 1, 2, 0/
      DATA WFCT /2, 2, 4, 53, 12, 15, 11, 11, 6, 8, 9, 0, 1, 0/
      DATA WFIL /0, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 0, 0/
      DATA X /0.0, 1.0/, Y /0.0, 1.0/
      N = 0
      NFAIL = 0
      CALL GOPWK(1, 1, GWSPNG)
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 1, 12345)
      CALL GOPWK(1, 1, GWSNUL)
      CALL GACWK(3)
      CALL GSCLIP(5)
      CALL GACWK(1)
      CALL GPL(1, X, Y)
      CALL GFA(0, X, Y)
      IDR(1) = 'abc'
      IDR(2) = 'name'
      CALL GESC(-5, 2, IDR, 1, LODR, ODR)
      CALL GESC(GESSFN, 2, IDR, 1, LODR, ODR)
      CALL GCLRWK(1, 9)
      CALL GUWK(1, -1)
      CALL GSDS(1, 7, GSUPPD)
      CALL GOPKS(6, -1)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      CALL GCLKS
      CALL CHKI('count', N, NW - 1, NFAIL)
      DO 10 I = 1, MIN(N, NW)
         CALL CHKI('ERRNR', ERRS(I), WERR(I), NFAIL)
         CALL CHKI('FCTID', FCTS(I), WFCT(I), NFAIL)
         CALL CHKI('ERRFIL', FILS(I), WFIL(I), NFAIL)
   10 CONTINUE
      CALL CHKI('ESCLIP', ESCLIP, 53, NFAIL)
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 GERHND PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 GERHND FAIL ', NFAIL
         STOP 1
      END IF
      END

      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
!     The application's ERROR HANDLING: records, never logs.
      INTEGER ERRNR, FCTID, ERRFIL
      INTEGER N, ERRS(20), FCTS(20), FILS(20)
      COMMON /ERRREC/ N, ERRS, FCTS, FILS
      IF (N .GE. 20) RETURN
      N = N + 1
      ERRS(N) = ERRNR
      FCTS(N) = FCTID
      FILS(N) = ERRFIL
      END
