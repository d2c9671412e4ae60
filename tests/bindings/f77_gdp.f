C     SPDX-License-Identifier: MIT
C     The GDPs from Fortran (issue 17 item 4): RAL gdpex's pie chart
C     (GDP -3, three points per sector, bundled fill attributes) drawn
C     solid and checked by GQPX, then hatched as gdpex draws it
C     (picture gks0-002.png); GQEGDP/GQGDP. Run with
C     GKS3D_ASF=BUNDLED. Prints FAIL lines and ALL OK when none failed.
      PROGRAM F77GDP
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      CHARACTER*80 NODAT(1)
      INTEGER NFAIL, IERR, I, N, IGDP, NB, IB(5), IC, IPASS
      REAL XC, YC, RADIUS, XA(3), YA(3), THETAD(3), PI, TH, THETAR
      DATA XC, YC, RADIUS /0.5, 0.5, 0.375/
      DATA THETAD /150.0, 115.0, 95.0/
      NFAIL = 0
      PI = 4.0 * ATAN(1.0)
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 0, GWSPNG)
      CALL GACWK(1)
      CALL GSWKVP(1, 0.0, 199.0, 0.0, 199.0)
      DO 40 IPASS = 1, 2
        DO 5 I = 1, 3
          IF (IPASS .EQ. 1) THEN
            CALL GSFAR(1, I, GSOLID, 1, I + 1)
          ELSE
            CALL GSFAR(1, I, GHATCH, -I, 1)
          END IF
    5   CONTINUE
        TH = 0.0
        XA(1) = XC + RADIUS * SIN(TH)
        YA(1) = YC + RADIUS * COS(TH)
        DO 20 I = 1, 3
          THETAR = THETAD(I) * PI / 360.0
          DO 10 N = 2, 3
            TH = TH + THETAR
            XA(N) = XC + RADIUS * SIN(TH)
            YA(N) = YC + RADIUS * COS(TH)
   10     CONTINUE
          CALL GSFAI(I)
          CALL GGDP(3, XA, YA, GPIE, 1, NODAT)
          XA(1) = XA(3)
          YA(1) = YA(3)
   20   CONTINUE
        IF (IPASS .EQ. 1) THEN
C         Sector centres at 75, 207.5 and 312.5 degrees from 12 o'clock.
          CALL PIXAT(75.0, 2, NFAIL)
          CALL PIXAT(207.5, 3, NFAIL)
          CALL PIXAT(312.5, 4, NFAIL)
          CALL GQPX(1, 0.5, 0.9, IERR, IC)
          CALL CHKI('outside the pie', IC, 0, NFAIL)
          CALL GCLRWK(1, GALWAY)
        END IF
   40 CONTINUE
C     The description table lists the GDPs.
      CALL GQEGDP(GWSPNG, 0, IERR, N, IGDP)
      CALL CHKI('GQEGDP errind', IERR, 0, NFAIL)
      CALL CHKI('GQEGDP count', N, 5, NFAIL)
      CALL GQEGDP(GWSPNG, 3, IERR, N, IGDP)
      CALL CHKI('GQEGDP third', IGDP, GPIE, NFAIL)
      CALL GQGDP(GWSPNG, GPIE, IERR, NB, IB)
      CALL CHKI('GQGDP errind', IERR, 0, NFAIL)
      CALL CHKI('GQGDP count', NB, 1, NFAIL)
      CALL CHKI('GQGDP fill', IB(1), GFAATT, NFAIL)
      CALL GQGDP(GWSPNG, GARC, IERR, NB, IB)
      CALL CHKI('GQGDP arc line', IB(1), GPLATT, NFAIL)
      CALL GQGDP(GWSPNG, 5, IERR, NB, IB)
      CALL CHKI('GQGDP unknown', IERR, 41, NFAIL)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) WRITE (*, *) 'ALL OK'
      END

      SUBROUTINE PIXAT(DEG, IWANT, NFAIL)
      REAL DEG, A
      INTEGER IWANT, NFAIL, IERR, IC
      A = DEG * 4.0 * ATAN(1.0) / 180.0
      CALL GQPX(1, 0.5 + 0.2 * SIN(A), 0.5 + 0.2 * COS(A), IERR, IC)
      CALL CHKI('sector colour', IC, IWANT, NFAIL)
      END

      SUBROUTINE CHKI(WHAT, IGOT, IWANT, NFAIL)
      CHARACTER*(*) WHAT
      INTEGER IGOT, IWANT, NFAIL
      IF (IGOT .NE. IWANT) THEN
        WRITE (*, *) 'FAIL ', WHAT, IGOT, IWANT
        NFAIL = NFAIL + 1
      END IF
      END
