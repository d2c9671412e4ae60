C     SPDX-License-Identifier: MIT
      PROGRAM VIEW3
!     The GKS-3D slice through the Fortran binding: GEVVWM (VUP before
!     VPN), GEVPJM, GSVWR, GSVWI, GSHRM, GFA3, GEVTM. Prints PASS or the
!     failing checks; the C checker then verifies the z-buffered PNG.
      IMPLICIT NONE
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER NFAIL, ERR, I, J
      REAL VWM(4,4), PRM(4,4), VCLP(6), PRVP(6), MOUT(2,3)
      REAL AX(4), AY(4), AZ(4), BX(4), BY(4), BZ(4)
      DATA VCLP /0.0, 1.0, 0.0, 1.0, 0.0, 1.0/
      DATA PRVP /0.0, 1.0, 0.0, 1.0, 0.0, 1.0/
      DATA AX /0.0, 1.0, 1.0, 0.0/, AY /0.0, 0.0, 0.5, 0.5/
      DATA AZ /0.0, 1.0, 1.0, 0.0/
      DATA BX /0.0, 1.0, 1.0, 0.0/, BY /0.0, 0.0, 0.5, 0.5/
      DATA BZ /1.0, 0.0, 0.0, 1.0/
      NFAIL = 0
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 3, GWSPNG)
      CALL GACWK(1)
      CALL GSWKWN(1, 0.0, 1.0, 0.0, 0.5)
      CALL GSWKVP(1, 0.0, 16.0, 0.0, 8.0)
!     Identity orientation: VRP 0, VUP +y, VPN +z (VUP comes first).
      CALL GEVVWM(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, GNDC,
     +            ERR, VWM)
      CALL CHKI('GEVVWM ERR', ERR, 0, NFAIL)
      DO 20 J = 1, 4
         DO 10 I = 1, 4
            IF (I .EQ. J) THEN
               CALL CHKR('VWM', VWM(I,J), 1.0, NFAIL)
            ELSE
               CALL CHKR('VWM', VWM(I,J), 0.0, NFAIL)
            END IF
   10    CONTINUE
   20 CONTINUE
!     VUP parallel to VPN: error 561 in ERR.
      CALL GEVVWM(0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 1.0, GNDC,
     +            ERR, PRM)
      CALL CHKI('GEVVWM parallel', ERR, 561, NFAIL)
      CALL GEVPJM(0.0, 1.0, 0.0, 1.0, PRVP, 0, 0.5, 0.5, 5.0,
     +            0.0, 0.0, 1.0, ERR, PRM)
      CALL CHKI('GEVPJM ERR', ERR, 0, NFAIL)
      CALL CHKR('PRM(3,3)', PRM(3,3), 1.0, NFAIL)
      CALL GSVWR(1, 1, VWM, PRM, VCLP, GCLIP, GCLIP, GCLIP)
      CALL GSVWI(1)
      CALL GSHRM(1, 2)
!     Two squares crossing at x = 0.5 (A red: z = x; B blue: z = 1-x).
      CALL GSFAIS(GSOLID)
      CALL GSFACI(2)
      CALL GFA3(4, AX, AY, AZ)
      CALL GSFACI(4)
      CALL GFA3(4, BX, BY, BZ)
!     GEVTM: rotation by 90 degrees about the origin, NDC.
      CALL GEVTM(0.0, 0.0, 0.0, 0.0, 1.5707964, 1.0, 1.0, GNDC, MOUT)
      CALL CHKR('MOUT(1,2)', MOUT(1,2), -1.0, NFAIL)
      CALL CHKR('MOUT(2,1)', MOUT(2,1), 1.0, NFAIL)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) WRITE (*, '(A)') 'F77 VIEW3 PASS'
      END
