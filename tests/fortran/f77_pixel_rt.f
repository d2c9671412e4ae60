C     SPDX-License-Identifier: MIT
      PROGRAM PIXRT
!     INQUIRE PIXEL ARRAY (GQPXA) and its dimensions (GQPXAD) from
!     Fortran on a ray-traced frame before it is written: the answer is
!     the picture UPDATE WORKSTATION then writes, so the array inquired
!     before the update equals, pixel by pixel, the one inquired after
!     it (read back from the written frame). A 32 x 32 PNG workstation,
!     ray tracing with its default sampling (anti-aliased edges), one
!     fill area over the middle: its pixels are not the background 0.
      IMPLICIT NONE
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER LASTE, LASTF, NERR
      COMMON /LASTER/ LASTE, LASTF, NERR
      INTEGER NFAIL, IERR, INV, N, M, I, J, NDIFF
      INTEGER A(32, 32), B(32, 32)
      REAL X(4), Y(4), Z(4)
      DATA X /0.25, 0.75, 0.75, 0.25/, Y /0.25, 0.25, 0.75, 0.75/
      DATA Z /0.5, 0.5, 0.5, 0.5/
      NFAIL = 0
      NERR = 0
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 0, GWSPNG)
      CALL GSHRM(1, GHRAYT)
      CALL GACWK(1)
      CALL GSWKVP(1, 0.0, 32.0, 0.0, 32.0)
      CALL GSFAIS(GSOLID)
      CALL GSFACI(2)
      CALL GFA3(4, X, Y, Z)
      CALL GQPXAD(1, 0.0, 1.0, 1.0, 0.0, IERR, N, M)
      CALL CHKI('GQPXAD errind', IERR, 0, NFAIL)
      CALL CHKI('GQPXAD N', N, 32, NFAIL)
      CALL CHKI('GQPXAD M', M, 32, NFAIL)
      CALL GQPXA(1, 0.5/32, 31.5/32, 32, 32, 1, 1, 32, 32, IERR,
     +           INV, A)
      CALL CHKI('GQPXA before update', IERR, 0, NFAIL)
      CALL CHKI('middle traced', MIN(ABS(A(16, 16)), 1), 1, NFAIL)
      CALL CHKI('corner background', A(1, 1), 0, NFAIL)
      CALL GUWK(1, GPERFO)
      CALL GQPXA(1, 0.5/32, 31.5/32, 32, 32, 1, 1, 32, 32, IERR,
     +           INV, B)
      CALL CHKI('GQPXA after update', IERR, 0, NFAIL)
      NDIFF = 0
      DO 20 J = 1, 32
         DO 10 I = 1, 32
            IF (A(I, J) .NE. B(I, J)) NDIFF = NDIFF + 1
   10    CONTINUE
   20 CONTINUE
      CALL CHKI('pixels differing from the written frame', NDIFF, 0,
     +          NFAIL)
      CALL CHKI('no error', NERR, 0, NFAIL)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 PIXEL RT PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 PIXEL RT FAILURES ', NFAIL
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
