C     SPDX-License-Identifier: MIT
      PROGRAM HELLO
!     gks3d FORTRAN 77 example: a red filled triangle and a blue
!     polyline (a closed square) on a PNG workstation. CONID 1 writes the file gks1.png.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER WKID, CONID
      PARAMETER (WKID=1, CONID=1)
      REAL TX(3), TY(3), LX(5), LY(5)
      DATA TX /0.1, 0.9, 0.5/, TY /0.1, 0.1, 0.9/
      DATA LX /0.05, 0.95, 0.95, 0.05, 0.05/
      DATA LY /0.05, 0.05, 0.95, 0.95, 0.05/
!     error messages go to unit 6 (standard output)
      CALL GOPKS(6, -1)
      CALL GOPWK(WKID, CONID, GWSPNG)
      CALL GACWK(WKID)
      CALL GSCR(WKID, 2, 1.0, 0.0, 0.0)
      CALL GSCR(WKID, 4, 0.0, 0.0, 1.0)
      CALL GSFAIS(GSOLID)
      CALL GSFACI(2)
      CALL GFA(3, TX, TY)
      CALL GSPLCI(4)
      CALL GPL(5, LX, LY)
      CALL GDAWK(WKID)
      CALL GCLWK(WKID)
      CALL GCLKS
      END
