C     SPDX-License-Identifier: MIT
      PROGRAM STATS
!     ESCAPE -108 (GESRST) from Fortran: the ray statistics of the last
!     traced picture. A 32 x 32 PNG workstation, ray tracing, 1 sample
!     per pixel, one fill area over the middle: 1024 eye rays, some but
!     not all of them hit, one primitive; times not negative; LODR = 2;
!     ODR(2) untouched with MLODR = 1; a malformed record gives 182.
      IMPLICIT NONE
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER LASTE, LASTF, NERR
      COMMON /LASTER/ LASTE, LASTF, NERR
      INTEGER NFAIL, LODR, N(8)
      REAL X(4), Y(4), Z(4), T(2)
      CHARACTER*80 IDR(1), ODR(2)
      DATA X /0.25, 0.75, 0.75, 0.25/, Y /0.25, 0.25, 0.75, 0.75/
      DATA Z /0.5, 0.5, 0.5, 0.5/
      NFAIL = 0
      NERR = 0
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 0, GWSPNG)
      CALL GSHRM(1, GHRAYT)
      CALL GACWK(1)
      CALL GSWKVP(1, 0.0, 32.0, 0.0, 32.0)
      WRITE (IDR(1), '(3I10)') 1, 1, 0
      CALL GESC(GESRSA, 1, IDR, 1, LODR, ODR)
      CALL GSFAIS(GSOLID)
      CALL GFA3(4, X, Y, Z)
      CALL GUWK(1, GPERFO)
      WRITE (IDR(1), '(I10)') 1
      ODR(1) = ' '
      ODR(2) = 'untouched'
      LODR = -1
      CALL GESC(GESRST, 1, IDR, 2, LODR, ODR)
      CALL CHKI('LODR', LODR, 2, NFAIL)
      READ (ODR(1), '(8I10)') N
      READ (ODR(2), '(2E20.8)') T
      CALL CHKI('eye rays', N(1), 1024, NFAIL)
      IF (N(2) .LE. 0 .OR. N(2) .GE. 1024) THEN
         WRITE (*, '(A, I0)') 'FAIL: eye rays that hit ', N(2)
         NFAIL = NFAIL + 1
      END IF
      CALL CHKI('primitives', N(8), 1, NFAIL)
      IF (T(1) .LT. 0.0 .OR. T(2) .LT. 0.0) THEN
         WRITE (*, '(A)') 'FAIL: negative time'
         NFAIL = NFAIL + 1
      END IF
      ODR(2) = 'untouched'
      CALL GESC(GESRST, 1, IDR, 1, LODR, ODR)
      CALL CHKI('LODR with MLODR 1', LODR, 1, NFAIL)
      IF (ODR(2) .NE. 'untouched') THEN
         WRITE (*, '(A)') 'FAIL: ODR(2) written with MLODR = 1'
         NFAIL = NFAIL + 1
      END IF
      CALL CHKI('no error', NERR, 0, NFAIL)
      IDR(1) = 'x'
      CALL GESC(GESRST, 1, IDR, 2, LODR, ODR)
      CALL CHKI('malformed record', LASTE, 182, NFAIL)
      CALL CHKI('LODR after error', LODR, 0, NFAIL)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 STATS PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 STATS FAILURES ', NFAIL
      END IF
      END

      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
      INTEGER ERRNR, FCTID, ERRFIL
      INTEGER LASTE, LASTF, NERR
      COMMON /LASTER/ LASTE, LASTF, NERR
      LASTE = ERRNR
      LASTF = FCTID
      NERR = NERR + 1
      IF (ERRFIL .LT. 0) NERR = -1000
      END
