C     SPDX-License-Identifier: MIT
      PROGRAM FDATA
!     The primitives with data through the Fortran binding (GFA3D,
!     GFAS3D, GTS3D, GQM3D, GSFA3D, GSISM, GSBISM, GQISM) onto a PNG
!     (gks21.png) and a metafile (gks22.gksm); f77_data_twin.c draws
!     the same through the C binding and f77_data_check compares both
!     outputs bit for bit. All values are exact binary fractions.
      IMPLICIT NONE
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER NFAIL, ERR, M1, M2, IDUM(1), I, J, K
      REAL RDUM(3)
      REAL AX(3), AY(3), AZ(3), AN(3), ACR(3,3), AVN(3,3)
      REAL BX(7), BY(7), BZ(7)
      INTEGER BLC(2), BCI(7)
      REAL SX(6), SY(6), SZ(6), SCR(3,4), SFN(3,4)
      REAL QX(6), QY(6), QZ(6), QVN(3,6)
      INTEGER QCI(6)
      REAL OX(5), OY(5), OZ(5), OFN(3,2), OCR(3,5)
      INTEGER NLPS(2), LCNT(3), IDX(10)
      DATA AX /0.125, 0.5, 0.25/, AY /0.125, 0.125, 0.375/
      DATA AZ /0.5, 0.5, 0.625/, AN /0.0, 0.0, 1.0/
      DATA ACR /1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0/
      DATA AVN /0.0, 0.0, 1.0, 0.25, 0.0, 1.0, 0.0, 0.25, 1.0/
      DATA BX /0.5, 0.875, 0.875, 0.5, 0.625, 0.75, 0.6875/
      DATA BY /0.5, 0.5, 0.875, 0.875, 0.5625, 0.5625, 0.75/
      DATA BZ /7*0.25/
      DATA BLC /4, 3/, BCI /2, 3, 1, 2, 3, 3, 2/
      DATA SX /0.0625, 0.125, 0.1875, 0.25, 0.3125, 0.375/
      DATA SY /0.5, 0.875, 0.5, 0.875, 0.5, 0.875/
      DATA SZ /0.25, 0.25, 0.375, 0.375, 0.5, 0.5/
      DATA SCR /1.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0,
     +          0.5, 0.5, 0.5/
      DATA SFN /0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0,
     +          0.0, 0.0, -1.0/
      DATA QX /0.5, 0.625, 0.75, 0.5, 0.625, 0.75/
      DATA QY /0.0625, 0.0625, 0.0625, 0.25, 0.25, 0.25/
      DATA QZ /0.5, 0.5, 0.5, 0.75, 0.75, 0.75/
      DATA QVN /0.0, 0.0, 1.0, 0.25, 0.0, 1.0, 0.5, 0.0, 1.0,
     +          0.0, 0.25, 1.0, 0.25, 0.25, 1.0, 0.5, 0.25, 1.0/
      DATA QCI /1, 2, 3, 2, 3, 1/
      DATA OX /0.8125, 0.9375, 0.9375, 0.8125, 0.875/
      DATA OY /0.0625, 0.0625, 0.375, 0.375, 0.25/
      DATA OZ /0.75, 0.75, 0.75, 0.75, 0.875/
      DATA OFN /0.0, -1.0, 1.0, 1.0, 1.0, 1.0/
      DATA OCR /1.0, 0.5, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0,
     +          0.25, 0.25, 0.25, 0.0, 1.0, 0.0/
      DATA NLPS /1, 2/, LCNT /3, 3, 4/
      DATA IDX /1, 2, 5, 2, 3, 5, 3, 4, 1, 5/
      NFAIL = 0
      IDUM(1) = 0
      DO 5 I = 1, 3
         RDUM(I) = 0.0
    5 CONTINUE
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 21, GWSPNG)
      CALL GOPWK(2, 22, GWSMO)
      CALL GACWK(1)
      CALL GACWK(2)
      DO 6 K = 1, 2
         CALL GSHRM(K, GHZBUF)
         CALL GSCR(K, 2, 0.75, 0.25, 0.125)
         CALL GSCR(K, 3, 0.125, 0.5, 0.875)
    6 CONTINUE
      CALL GSFAIS(GSOLID)
      CALL GSISM(GSHCOL)
      CALL GSBISM(GSHNOR)
      CALL GQISM(ERR, M1, M2)
      IF (ERR .NE. 0 .OR. M1 .NE. GSHCOL .OR. M2 .NE. GSHNOR) THEN
         WRITE (*, *) 'FAIL GQISM', ERR, M1, M2
         NFAIL = NFAIL + 1
      END IF
      CALL GFA3D(GFNORM, GVCONO, GCRGB, 3, IDUM, RDUM, AN,
     +           AX, AY, AZ, IDUM, ACR, AVN)
      CALL GSEDFG(GON)
      CALL GFAS3D(GFCOLR, GVCOLR, GCINDI, 2, BLC, 3, RDUM, RDUM,
     +            BX, BY, BZ, BCI, RDUM, RDUM)
      CALL GSEDFG(GOFF)
      CALL GTS3D(GFCONO, GVCOOR, GCRGB, 6, IDUM, SCR, SFN,
     +           SX, SY, SZ, IDUM, RDUM, RDUM)
      CALL GQM3D(GFNONE, GVCONO, GCINDI, 3, 2, IDUM, RDUM, RDUM,
     +           QX, QY, QZ, QCI, RDUM, QVN)
      CALL GSFA3D(GFNORM, GVCOLR, GCRGB, 2, NLPS, LCNT, IDX,
     +            IDUM, RDUM, OFN, 5, OX, OY, OZ, IDUM, OCR, RDUM)
      CALL GDAWK(2)
      CALL GDAWK(1)
      CALL GCLWK(2)
      CALL GCLWK(1)
      CALL GCLKS
      J = NFAIL
      IF (J .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 DATA PASS'
      ELSE
         WRITE (*, '(A,I4)') 'F77 DATA FAIL', J
      END IF
      END
