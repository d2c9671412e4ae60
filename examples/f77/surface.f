C     SPDX-License-Identifier: MIT
      PROGRAM SURFAC
C     A scientist's picture: the surface z = f(x, y) of a damped ripple
C     on a 32 x 32 grid, each grid cell emitted as FILL AREA 3 (split
C     into two triangles, since a fill area is planar), coloured by
C     height, ray traced above a mirror plane that shows its underside.
C     The data stay in the scientist's own coordinates: SET WINDOW 3
C     and SET VIEWPORT 3 map them to NDC3, and the view's up vector is
C     the z axis. A z-buffer preview at a third of the size comes first.
C     Then the same surface drawn WITH DATA (FILL AREA 3 WITH DATA,
C     interior shading method normal interpolation): vertex colours by
C     height and vertex normals from the analytic gradient, so that it
C     is shaded smooth.
C
C     Usage: surface_f77 [SIZE [PREFIX [TYPE]]] (SIZE = viewport in
C     pixels, 24..2048, default 480; TYPE png (default), pdf, svg, ps or
C     eps); writes PREFIXsurface_zbuffer.png, PREFIXsurface.png,
C     PREFIXsurface_smooth_zbuffer.png and PREFIXsurface_smooth.png (or
C     .pdf ...). C twin: examples/c/surface.c (same files).
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER N
      PARAMETER (N=32)
      REAL X(N+1), Y(N+1), Z(N+1,N+1), R2, R, S, DR
      REAL G(2,N+1,N+1)
      INTEGER I, J, SIZE, IOS, NP, NBLEN, WTYPE
      CHARACTER*256 ARG, PREFIX
      COMMON /SURTYP/ WTYPE
      SIZE = 480
      PREFIX = ' '
      IF (COMMAND_ARGUMENT_COUNT() .GE. 1) THEN
         CALL GET_COMMAND_ARGUMENT(1, ARG)
         READ (ARG, *, IOSTAT=IOS) SIZE
         IF (IOS .NE. 0 .OR. SIZE .LT. 24 .OR. SIZE .GT. 2048) THEN
            WRITE (*, '(A)')
     +         'usage: surface_f77 [SIZE (24..2048) [PREFIX]]'
            STOP 2
         END IF
      END IF
      IF (COMMAND_ARGUMENT_COUNT() .GE. 2) THEN
         CALL GET_COMMAND_ARGUMENT(2, PREFIX)
      END IF
      NP = NBLEN(PREFIX)
      IF (NP .GT. 200) STOP 2
      WTYPE = GWSPNG
      IF (COMMAND_ARGUMENT_COUNT() .GE. 3) THEN
         CALL GET_COMMAND_ARGUMENT(3, ARG)
         WTYPE = 0
         IF (ARG .EQ. 'png') WTYPE = GWSPNG
         IF (ARG .EQ. 'pdf') WTYPE = GWSPDF
         IF (ARG .EQ. 'svg') WTYPE = GWSSVG
         IF (ARG .EQ. 'ps') WTYPE = GWSPS
         IF (ARG .EQ. 'eps') WTYPE = GWSEPS
         IF (WTYPE .EQ. 0) STOP 2
      END IF
C     the data: x, y in [-2, 2]
      DO 10 I = 1, N + 1
         X(I) = -2.0 + 4.0 * REAL(I - 1) / REAL(N)
         Y(I) = X(I)
   10 CONTINUE
C     NOVECTOR: gfortran -O3 would otherwise call glibc's vector COS
C     and EXP (libmvec, a few ulps off), even without -ffast-math, and
C     the heights would no longer match the C twin's cosf and expf.
      DO 30 J = 1, N + 1
!GCC$ NOVECTOR
         DO 20 I = 1, N + 1
            R2 = X(I) * X(I) + Y(J) * Y(J)
            Z(I,J) = 0.8 * COS(2.5 * SQRT(R2)) * EXP(-0.25 * R2)
C           the gradient: (df/dr) / r = 0.8 exp(-r^2/4) (-2.5 sin(2.5 r)
C           / r - 0.5 cos(2.5 r)), sin(2.5 r) / r -> 2.5 at r = 0
            R = SQRT(R2)
            IF (R .GT. 0.0) THEN
               S = -2.5 * SIN(2.5 * R) / R
            ELSE
               S = -6.25
            END IF
            DR = 0.8 * EXP(-0.25 * R2) * (S - 0.5 * COS(2.5 * R))
            G(1,I,J) = DR * X(I)
            G(2,I,J) = DR * Y(J)
   20    CONTINUE
   30 CONTINUE
      CALL GOPKS(6, -1)
      CALL SURPIC(PREFIX(1:NP) // 'surface_zbuffer', SIZE / 3, GHZBUF,
     +            N, X, Y, Z, G, 0)
      CALL SURPIC(PREFIX(1:NP) // 'surface', SIZE, GHRAYT, N, X, Y, Z,
     +            G, 0)
      CALL SURPIC(PREFIX(1:NP) // 'surface_smooth_zbuffer', SIZE / 3,
     +            GHZBUF, N, X, Y, Z, G, 1)
      CALL SURPIC(PREFIX(1:NP) // 'surface_smooth', SIZE, GHRAYT, N, X,
     +            Y, Z, G, 1)
      CALL GCLKS
      END

      SUBROUTINE SURPIC(BASE, SIZE, MODE, N, X, Y, Z, G, SMOOTH)
C     One picture of the surface on workstation 1: file BASE.png,
C     viewport SIZE x SIZE pixels, HLHSR mode MODE; SMOOTH = 1: the
C     triangles WITH DATA (vertex colours by height, normals from the
C     gradient G), shading method normal interpolation.
      CHARACTER*(*) BASE
      INTEGER SIZE, MODE, N, SMOOTH
      REAL X(N+1), Y(N+1), Z(N+1,N+1), G(2,N+1,N+1)
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER WS, NC
      PARAMETER (WS=1, NC=16)
      INTEGER I, J, K, C, LODR, NB, NBLEN, ACT(2), DEACT(1)
      REAL WN(6), VP(6), PRVP(6), CLIP(6), VWM(4,4), PRM(4,4)
      REAL WHITE(3), AMB(3), LAMP(3), ORIGIN(3), DIRN(3), ATT(2)
      REAL T, PX(4), PY(4), PZ(4), ZM
      REAL VCR(3,3), VN(3,3), FCR(3), FN(3)
      INTEGER VCI(3), FCI(1), II(3), JJ(3), V
      CHARACTER*80 IDR(4), ODR(1)
      INTEGER ERR, WTYPE
      REAL SIDE
      COMMON /SURTYP/ WTYPE
      DATA WN /-2.5, 2.5, -2.5, 2.5, -1.5, 1.5/
      DATA VP /0.0, 1.0, 0.0, 1.0, 0.2, 0.8/
      DATA PRVP /0.0, 1.0, 0.0, 1.0, 0.0, 1.0/
      DATA CLIP /0.0, 1.0, 0.0, 1.0, 0.0, 1.0/
      DATA WHITE /1.0, 1.0, 1.0/, AMB /0.3, 0.3, 0.3/
      DATA LAMP /0.3, 0.1, 1.4/, ORIGIN /0.0, 0.0, 0.0/
      DATA DIRN /0.0, 0.0, -1.0/, ATT /1.0, 0.0/
      DATA ACT /2, 3/, DEACT /0/
      CALL GOPWK(WS, 1, WTYPE)
      NB = NBLEN(BASE)
      WRITE (IDR(1), '(I10)') WS
      DO 5 J = 1, (NB + 79) / 80
         IDR(J + 1) = BASE(80 * J - 79 : MIN(80 * J, NB))
    5 CONTINUE
      CALL GESC(GESSFN, (NB + 79) / 80 + 1, IDR, 1, LODR, ODR)
      CALL GSHRM(WS, MODE)
      CALL GACWK(WS)
      CALL GSWKWN(WS, 0.0, 1.0, 0.0, 1.0)
C     vector types: a side of SIZE x 0.2 mm (their nominal unit in the
C     place of a pixel)
      SIDE = REAL(SIZE)
      IF (WTYPE .NE. GWSPNG) SIDE = REAL(SIZE) * 0.0002
      CALL GSWKVP(WS, 0.0, SIDE, 0.0, SIDE)
C     the scientist's coordinates -> NDC3 (uniform scale 0.2)
      CALL GSW3(1, WN)
      CALL GSV3(1, VP)
      CALL GSELNT(1)
C     camera: z up (VUP comes before VPN in GEVVWM)
      CALL GEVVWM(0.5, 0.5, 0.45, 0.0, 0.0, 1.0, 1.0, -1.4, 1.1,
     +            GNDC, ERR, VWM)
      CALL GEVPJM(-0.62, 0.62, -0.62, 0.62, PRVP, GPERS,
     +            0.0, 0.0, 2.5, 0.0, -1.0, 1.0, ERR, PRM)
      CALL GSVWR(WS, 1, VWM, PRM, CLIP, GCLIP, GCLIP, GCLIP)
      CALL GSVWI(1)
C     colour map 16..31 from blue (low) to red (high); 14 the mirror
      DO 10 C = 0, NC - 1
         T = REAL(C) / REAL(NC - 1)
         CALL GSCR(WS, 16 + C, 0.15 + 0.8 * T,
     +             0.3 + 0.5 * (1.0 - ABS(2.0 * T - 1.0)),
     +             0.85 - 0.75 * T)
   10 CONTINUE
      CALL GSCR(WS, 14, 0.6, 0.65, 0.7)
      CALL GSLSR(WS, 2, GAMB, AMB, ORIGIN, DIRN, ATT, 0.0, 0.0)
      CALL GSLSR(WS, 3, GPOSI, WHITE, LAMP, DIRN, ATT, 0.0, 0.0)
      IF (MODE .EQ. GHRAYT) THEN
         WRITE (IDR(1), '(3I10)') WS, 4, 0
         CALL GESC(GESRSA, 1, IDR, 1, LODR, ODR)
      END IF
      CALL GSFAIS(GSOLID)
      CALL GSLSS(2, ACT, 0, DEACT)
      CALL GSRFEQ(GRAMDS)
      CALL GSBRFQ(GRAMDS)
C     the mirror plane below the surface
      CALL GSAPR(0.1, 0.2, 0.8, WHITE, 100.0, 0.0, 1.0)
      CALL GSBAPR(0.1, 0.2, 0.8, WHITE, 100.0, 0.0, 1.0)
      CALL GSFACI(14)
      PX(1) = -2.5
      PY(1) = -2.5
      PX(2) = 2.5
      PY(2) = -2.5
      PX(3) = 2.5
      PY(3) = 2.5
      PX(4) = -2.5
      PY(4) = 2.5
      DO 15 K = 1, 4
         PZ(K) = -1.2
   15 CONTINUE
      CALL GFA3(4, PX, PY, PZ)
C     the surface: two triangles per grid cell, colour by mean height
C     (flat), or with vertex data (SMOOTH = 1)
      CALL GSAPR(0.7, 0.8, 0.3, WHITE, 30.0, 0.0, 1.0)
      CALL GSBAPR(0.7, 0.8, 0.3, WHITE, 30.0, 0.0, 1.0)
      IF (SMOOTH .EQ. 1) THEN
         CALL GSISM(GSHNOR)
         CALL GSBISM(GSHNOR)
      END IF
      DO 30 J = 1, N
         DO 20 I = 1, N
            IF (SMOOTH .EQ. 1) THEN
C              (i,j) (i+1,j) (i+1,j+1), then (i,j) (i+1,j+1) (i,j+1)
               DO 18 K = 1, 2
                  II(1) = I
                  JJ(1) = J
                  II(2) = I + 1
                  JJ(2) = J
                  II(3) = I + 1
                  JJ(3) = J + 1
                  IF (K .EQ. 2) THEN
                     JJ(2) = J + 1
                     II(3) = I
                  END IF
                  DO 17 V = 1, 3
                     PX(V) = X(II(V))
                     PY(V) = Y(JJ(V))
                     PZ(V) = Z(II(V),JJ(V))
                     CALL SURCOL(PZ(V), VCR(1,V))
                     VN(1,V) = -G(1,II(V),JJ(V))
                     VN(2,V) = -G(2,II(V),JJ(V))
                     VN(3,V) = 1.0
   17             CONTINUE
                  CALL GFA3D(GFNONE, GVCONO, GCRGB, 3, FCI, FCR, FN,
     +                       PX, PY, PZ, VCI, VCR, VN)
   18          CONTINUE
               GO TO 20
            END IF
            ZM = 0.25 * (((Z(I,J) + Z(I+1,J)) + Z(I+1,J+1)) + Z(I,J+1))
            C = INT((ZM + 0.8) / 1.6 * REAL(NC))
            CALL GSFACI(16 + MAX(0, MIN(NC - 1, C)))
            PX(1) = X(I)
            PY(1) = Y(J)
            PZ(1) = Z(I,J)
            PX(2) = X(I+1)
            PY(2) = Y(J)
            PZ(2) = Z(I+1,J)
            PX(3) = X(I+1)
            PY(3) = Y(J+1)
            PZ(3) = Z(I+1,J+1)
            CALL GFA3(3, PX, PY, PZ)
            PX(2) = PX(3)
            PY(2) = PY(3)
            PZ(2) = PZ(3)
            PX(3) = X(I)
            PY(3) = Y(J+1)
            PZ(3) = Z(I,J+1)
            CALL GFA3(3, PX, PY, PZ)
   20    CONTINUE
   30 CONTINUE
      CALL GDAWK(WS)
      CALL GCLWK(WS)
      END

      SUBROUTINE SURCOL(H, RGB)
C     The colour of height H: the colour map 16..31 as a continuous
C     function.
      REAL H, RGB(3), T
      T = (H + 0.8) / 1.6
      T = MAX(0.0, MIN(1.0, T))
      RGB(1) = 0.15 + 0.8 * T
      RGB(2) = 0.3 + 0.5 * (1.0 - ABS(2.0 * T - 1.0))
      RGB(3) = 0.85 - 0.75 * T
      END

      INTEGER FUNCTION NBLEN(S)
C     Length of S without trailing blanks.
      CHARACTER*(*) S
      DO 10 NBLEN = LEN(S), 1, -1
         IF (S(NBLEN:NBLEN) .NE. ' ') RETURN
   10 CONTINUE
      NBLEN = 0
      END
