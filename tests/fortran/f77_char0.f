C     SPDX-License-Identifier: MIT
      PROGRAM CHAR0
!     Issue 20: CHAR(0) inside a TEXT string is error 101 (the C string
!     must not end there and draw "AB" silently); the same text without
!     it draws with no error.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INCLUDE 'GKSE_PAR'
      INTEGER N, ERRS(20), FCTS(20), FILS(20)
      COMMON /ERRREC/ N, ERRS, FCTS, FILS
      INTEGER NFAIL
      REAL TDX(2), TDY(2), TDZ(2)
      DATA TDX /1.0, 0.0/, TDY /0.0, 1.0/, TDZ /0.0, 0.0/
      N = 0
      NFAIL = 0
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 1, GWSNUL)
      CALL GACWK(1)
      CALL GTX(0.1, 0.1, 'ABCD')
      CALL CHKI('clean count', N, 0, NFAIL)
      CALL GTX(0.1, 0.1, 'AB'//CHAR(0)//'CD')
      CALL CHKI('count', N, 1, NFAIL)
      CALL CHKI('ERRNR', ERRS(1), 101, NFAIL)
      CALL CHKI('FCTID', FCTS(1), ETX, NFAIL)
      CALL GTX3(0.1, 0.1, 0.0, TDX, TDY, TDZ, CHAR(0)//'CD')
      CALL CHKI('count 3', N, 2, NFAIL)
      CALL CHKI('ERRNR 3', ERRS(2), 101, NFAIL)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 CHAR0 PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 CHAR0 FAIL ', NFAIL
         STOP 1
      END IF
      END

      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
!     Records the errors, never logs.
      INTEGER ERRNR, FCTID, ERRFIL
      INTEGER N, ERRS(20), FCTS(20), FILS(20)
      COMMON /ERRREC/ N, ERRS, FCTS, FILS
      N = N + 1
      IF (N .LE. 20) THEN
         ERRS(N) = ERRNR
         FCTS(N) = FCTID
         FILS(N) = ERRFIL
      END IF
      END
