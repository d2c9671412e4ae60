C     SPDX-License-Identifier: MIT
      PROGRAM SEGS
!     Segment functions through the Fortran binding: the state
!     machine, errors reported to GERHND, attributes round trip
!     (GSSGT3 / GQSGA3, GSSGT / GQSGA), list inquiries.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER NFAIL, IERR, I1, IOL, IVIS, IHIL, IDET, I, J
      REAL SM(3,4), SG(3,4), S2(2,3), G2(2,3), PRI
      REAL W6(6), R6(6), C6(6), V6(6), D6(6)
      NFAIL = 0
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 0, GWSNUL)
      CALL GACWK(1)
      CALL GCRSG(4)
      CALL GQOPS(I1)
      CALL CHKI('GQOPS SGOP', I1, GSGOP, NFAIL)
      CALL GQOPSG(IERR, I1)
      CALL CHKI('GQOPSG errind', IERR, 0, NFAIL)
      CALL CHKI('GQOPSG name', I1, 4, NFAIL)
      CALL GCLSG
      CALL GQOPSG(IERR, I1)
      CALL CHKI('GQOPSG closed errind', IERR, 4, NFAIL)
!     3x4 matrix with distinct elements, exact in REAL
      DO 20 J = 1, 4
        DO 10 I = 1, 3
          SM(I,J) = REAL(10*I + J) / 8.0
   10   CONTINUE
   20 CONTINUE
      CALL GSSGT3(4, SM)
      CALL GSVIS(4, GINVIS)
      CALL GSHLIT(4, GHILIT)
      CALL GSSGP(4, 0.25)
      CALL GSDTEC(4, GDETEC)
      CALL GQSGA3(4, IERR, SG, IVIS, IHIL, PRI, IDET)
      CALL CHKI('GQSGA3 errind', IERR, 0, NFAIL)
      DO 40 J = 1, 4
        DO 30 I = 1, 3
          CALL CHKR('GQSGA3 SEGTM', SG(I,J), SM(I,J), NFAIL)
   30   CONTINUE
   40 CONTINUE
      CALL CHKI('GQSGA3 VIS', IVIS, GINVIS, NFAIL)
      CALL CHKI('GQSGA3 HIL', IHIL, GHILIT, NFAIL)
      CALL CHKR('GQSGA3 PRI', PRI, 0.25, NFAIL)
      CALL CHKI('GQSGA3 DET', IDET, GDETEC, NFAIL)
      S2(1,1) = 1.0
      S2(2,1) = 0.0
      S2(1,2) = 0.0
      S2(2,2) = 2.0
      S2(1,3) = 0.5
      S2(2,3) = -0.25
      CALL GSSGT(4, S2)
      CALL GQSGA(4, IERR, G2, IVIS, IHIL, PRI, IDET)
      DO 60 J = 1, 3
        DO 50 I = 1, 2
          CALL CHKR('GQSGA SEGTM', G2(I,J), S2(I,J), NFAIL)
   50   CONTINUE
   60 CONTINUE
      CALL GCRSG(9)
      CALL GCLSG
      CALL GQSGUS(0, IERR, IOL, I1)
      CALL CHKI('GQSGUS count', IOL, 2, NFAIL)
      CALL GQSGUS(2, IERR, IOL, I1)
      CALL CHKI('GQSGUS(2)', I1, 9, NFAIL)
      CALL GQSGWK(1, 1, IERR, IOL, I1)
      CALL CHKI('GQSGWK(1)', I1, 4, NFAIL)
      CALL GQASWK(9, 1, IERR, IOL, I1)
      CALL CHKI('GQASWK(1)', I1, 1, NFAIL)
      CALL GQASWK(9, 2, IERR, IOL, I1)
      CALL CHKI('GQASWK(2) errind', IERR, 2002, NFAIL)
      CALL GRENSG(9, 11)
      CALL GQSGUS(2, IERR, IOL, I1)
      CALL CHKI('GRENSG', I1, 11, NFAIL)
      CALL GDSG(11)
      CALL GQSGUS(0, IERR, IOL, I1)
      CALL CHKI('GDSG count', IOL, 1, NFAIL)
      CALL GDSGWK(1, 4)
      CALL GQSGUS(0, IERR, IOL, I1)
      CALL CHKI('GDSGWK count', IOL, 0, NFAIL)
      CALL GQSGP(GWSPNG, IERR, I1)
      CALL CHKI('GQSGP', I1, 0, NFAIL)
!     input priorities and workstation transformation 3
      CALL GSVPIP(3, 0, GHIGHR)
      CALL GQENTN(1, IERR, IOL, I1)
      CALL CHKI('GQENTN(1)', I1, 3, NFAIL)
      CALL CHKI('GQENTN count', IOL, 32, NFAIL)
      CALL GSVTIP(1, 2, 0, GHIGHR)
      CALL GQEVWI(1, 1, IERR, IOL, I1)
      CALL CHKI('GQEVWI(1)', I1, 2, NFAIL)
      W6(1) = 0.0
      W6(2) = 0.5
      W6(3) = 0.25
      W6(4) = 0.75
      W6(5) = 0.0
      W6(6) = 1.0
      CALL GSWKW3(1, W6)
      CALL GQWKT3(1, IERR, I1, R6, C6, V6, D6)
      CALL CHKI('GQWKT3 errind', IERR, 0, NFAIL)
      DO 70 I = 1, 6
        CALL CHKR('GQWKT3 RWINDO', R6(I), W6(I), NFAIL)
   70 CONTINUE
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) THEN
        PRINT *, 'F77 SEGMENTS PASS'
      ELSE
        PRINT *, 'F77 SEGMENTS FAIL', NFAIL
      END IF
      END
