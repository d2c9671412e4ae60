C     SPDX-License-Identifier: MIT
C     figlib.f -- the paper's pictures (Urban & Haberstroh 1992,
C     Fig. 2-5) through the FORTRAN 77 binding: scenes, workstation
C     set-up and the preview-then-render loop shared by fig2.f ...
C     fig5.f. examples/c/fig_scene.c makes the same calls with the same
C     numbers in the same order: both write byte-identical PNG files.
C
C     A program previews its scene with each classic HLHSR mode (none,
C     hidden line, z-buffer, painter) on a workstation of a third of
C     the size -- a low-resolution preview is just a smaller workstation
C     viewport -- and then draws the main picture (classic or ray
C     traced). A mode the workstation lacks (SET HLHSR MODE reports
C     error 511) is skipped with a note.
C
C     Only standard binding calls and the gks3d lighting extension
C     (GSAPR, GSBAPR, GSRFEQ, GSBRFQ, GSLSR, GSLSS). The command line
C     [SIZE [PREFIX]] is read with GET_COMMAND_ARGUMENT, the one
C     Fortran 2003 intrinsic used.

      SUBROUTINE FIGRUN(NAME, SCENE, MMODE, CLIPSR)
C     Runs one picture program. NAME: file name stem (fig2 ...);
C     SCENE: 1 board (lit), 2 ventilator, 3 board in flat colours
C     (no lighting model); MMODE: HLHSR mode of the main
C     picture; CLIPSR: 1 = secondary rays clipped (ESCAPE GESRCS).
C     Command line: SIZE (viewport in pixels, 24..2048, default 480),
C     PREFIX (prepended to the file names). Stops with code 1 when GKS
C     reported an error, 2 for bad arguments.
      CHARACTER*(*) NAME
      INTEGER SCENE, MMODE, CLIPSR
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER NMODES
      PARAMETER (NMODES=4)
      INTEGER MODES(NMODES), SIZE, IOS, M, NP, NBLEN, WTYPE
      INTEGER LASTE, NERRS
      COMMON /FIGERR/ LASTE, NERRS
      CHARACTER*10 MNAMES(NMODES)
      CHARACTER*256 ARG, PREFIX, BASE
      DATA MODES /GHNONE, GHLINE, GHZBUF, GHPNTR/
      DATA MNAMES /'none', 'hiddenline', 'zbuffer', 'painter'/
      LASTE = 0
      NERRS = 0
      SIZE = 480
      PREFIX = ' '
      IF (COMMAND_ARGUMENT_COUNT() .GE. 1) THEN
         CALL GET_COMMAND_ARGUMENT(1, ARG)
         READ (ARG, *, IOSTAT=IOS) SIZE
         IF (IOS .NE. 0 .OR. SIZE .LT. 24 .OR. SIZE .GT. 2048) THEN
            WRITE (*, '(A)')
     +         'usage: PROGRAM [SIZE (24..2048, default 480) [PREFIX]]'
            STOP 2
         END IF
      END IF
      IF (COMMAND_ARGUMENT_COUNT() .GE. 2) THEN
         CALL GET_COMMAND_ARGUMENT(2, PREFIX)
      END IF
      WTYPE = GWSPNG
      IF (COMMAND_ARGUMENT_COUNT() .GE. 3) THEN
         CALL GET_COMMAND_ARGUMENT(3, ARG)
         WTYPE = 0
         IF (ARG .EQ. 'png') WTYPE = GWSPNG
         IF (ARG .EQ. 'pdf') WTYPE = GWSPDF
         IF (ARG .EQ. 'svg') WTYPE = GWSSVG
         IF (ARG .EQ. 'ps') WTYPE = GWSPS
         IF (ARG .EQ. 'eps') WTYPE = GWSEPS
         IF (WTYPE .EQ. 0) THEN
            WRITE (*, '(A)') 'usage: PROGRAM [SIZE [PREFIX '//
     +         '[png|pdf|svg|ps|eps]]]'
            STOP 2
         END IF
      END IF
      NP = NBLEN(PREFIX)
      IF (NP .GT. 200) THEN
         WRITE (*, '(A)') 'PREFIX too long'
         STOP 2
      END IF
      CALL GOPKS(6, -1)
      DO 10 M = 1, NMODES
         BASE = PREFIX(1:NP) // NAME // '_' // MNAMES(M)
         CALL PICTUR(BASE, SIZE / 3, MODES(M), SCENE, 0, WTYPE)
   10 CONTINUE
      BASE = PREFIX(1:NP) // NAME
      CALL PICTUR(BASE, SIZE, MMODE, SCENE, CLIPSR, WTYPE)
      CALL GCLKS
      IF (NERRS .GT. 0) STOP 1
      END

      SUBROUTINE PICTUR(BASE, SIZE, MODE, SCENE, CLIPSR, WTYPE)
C     One picture on workstation 1 of type WTYPE: file BASE.png,
C     viewport SIZE x SIZE pixels (vector types: SIZE x 0.2 mm, their
C     nominal unit in the place of a pixel), HLHSR mode MODE.
      CHARACTER*(*) BASE
      INTEGER SIZE, MODE, SCENE, CLIPSR, WTYPE
      REAL SIDE
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER WS
      PARAMETER (WS=1)
      INTEGER LASTE, NERRS
      COMMON /FIGERR/ LASTE, NERRS
      INTEGER NB, NREC, J, LODR, NBLEN, ACT(2), DEACT(1)
      REAL WHITE(3), ORIGIN(3), AMB(3), LAMPB(3), LAMPF(3)
      CHARACTER*80 IDR(5), ODR(1)
      DATA WHITE /1.0, 1.0, 1.0/, ORIGIN /0.0, 0.0, 0.0/
      DATA AMB /0.25, 0.25, 0.25/
      DATA LAMPB /0.2, 0.95, 0.85/, LAMPF /0.4, 1.3, 0.65/
      DATA ACT /2, 3/, DEACT /0/
      CALL GOPWK(WS, 1, WTYPE)
C     ESCAPE set file name: IDR(1) = workstation, IDR(2...) = the name
      NB = NBLEN(BASE)
      NREC = (NB + 79) / 80
      WRITE (IDR(1), '(I10)') WS
      DO 10 J = 1, NREC
         IDR(J + 1) = BASE(80 * J - 79 : MIN(80 * J, NB))
   10 CONTINUE
      CALL GESC(GESSFN, NREC + 1, IDR, 1, LODR, ODR)
      LASTE = 0
      CALL GSHRM(WS, MODE)
      IF (LASTE .EQ. 511) THEN
         CALL GCLWK(WS)
C        the background picture of the unused workstation
         OPEN (UNIT=91, FILE=BASE(1:NB) // '.png', STATUS='OLD',
     +         IOSTAT=J)
         IF (J .EQ. 0) CLOSE (UNIT=91, STATUS='DELETE')
         WRITE (*, '(A, I2, A, A, A)') 'HLHSR mode', MODE,
     +      ' not available: ', BASE(1:NB), '.png skipped'
         RETURN
      END IF
      CALL GACWK(WS)
C     colour 0 first: the picture is cleared to it when the viewport
C     sets its size
      CALL GSCR(WS, 0, 0.1, 0.11, 0.14)
      CALL GSCR(WS, 2, 0.85, 0.15, 0.1)
      CALL GSCR(WS, 8, 0.9, 0.9, 0.85)
      CALL GSCR(WS, 9, 0.15, 0.2, 0.45)
      CALL GSCR(WS, 10, 0.75, 0.75, 0.8)
      CALL GSCR(WS, 11, 0.8, 0.95, 0.9)
      CALL GSCR(WS, 12, 0.9, 0.6, 0.15)
      CALL GSCR(WS, 13, 0.3, 0.3, 0.3)
      CALL GSWKWN(WS, 0.0, 1.0, 0.0, 1.0)
      SIDE = REAL(SIZE)
      IF (WTYPE .NE. GWSPNG) SIDE = REAL(SIZE) * 0.0002
      CALL GSWKVP(WS, 0.0, SIDE, 0.0, SIDE)
      CALL VIEW(WS, SCENE)
      CALL LIGHT(WS, 2, GAMB, AMB, ORIGIN)
      IF (SCENE .EQ. 2) THEN
         CALL LIGHT(WS, 3, GPOSI, WHITE, LAMPF)
      ELSE
         CALL LIGHT(WS, 3, GPOSI, WHITE, LAMPB)
      END IF
      IF (MODE .EQ. GHRAYT) THEN
C        2 x 2 samples per pixel; secondary rays clipped or not
         WRITE (IDR(1), '(3I10)') WS, 4, 0
         CALL GESC(GESRSA, 1, IDR, 1, LODR, ODR)
         WRITE (IDR(1), '(2I10)') WS, CLIPSR
         CALL GESC(GESRCS, 1, IDR, 1, LODR, ODR)
      END IF
      CALL GSVWI(1)
      CALL GSFAIS(GSOLID)
      CALL GSLSS(2, ACT, 0, DEACT)
      IF (SCENE .EQ. 2) THEN
         CALL SCNFAN
      ELSE
         CALL SCNBRD(SCENE .EQ. 1)
      END IF
      CALL GDAWK(WS)
      CALL GCLWK(WS)
      END

      SUBROUTINE VIEW(WS, SCENE)
C     View 1: the paper's camera above the front right of the board;
C     the ventilator scene clips NPC3 y above 0.7 (its far half).
      INTEGER WS, SCENE
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER ERR
      REAL VWM(4,4), PRM(4,4), PRVP(6), CLIPB(6), CLIPF(6)
      DATA PRVP /0.0, 1.0, 0.0, 1.0, 0.0, 1.0/
      DATA CLIPB /0.0, 1.0, 0.0, 1.0, 0.0, 1.0/
      DATA CLIPF /0.0, 1.0, 0.0, 0.7, 0.0, 1.0/
C     VRP, then VUP BEFORE VPN (GKSGRAL-3D order)
      CALL GEVVWM(0.5, 0.3, 0.5, 0.0, 1.0, 0.0, 0.35, 0.55, 1.0,
     +            GNDC, ERR, VWM)
      CALL GEVPJM(-0.55, 0.55, -0.55, 0.55, PRVP, GPERS,
     +            0.0, 0.0, 2.5, 0.0, -1.0, 1.0, ERR, PRM)
      IF (SCENE .EQ. 2) THEN
         CALL GSVWR(WS, 1, VWM, PRM, CLIPF, GCLIP, GCLIP, GCLIP)
      ELSE
         CALL GSVWR(WS, 1, VWM, PRM, CLIPB, GCLIP, GCLIP, GCLIP)
      END IF
      END

      SUBROUTINE LIGHT(WS, LSI, TYPE, COLR, POS)
C     Light source LSI of type TYPE, colour COLR, position POS (NDC3).
      INTEGER WS, LSI, TYPE
      REAL COLR(3), POS(3)
      REAL DIRN(3), ATT(2)
      DATA DIRN /0.0, 0.0, -1.0/, ATT /1.0, 0.0/
      CALL GSLSR(WS, LSI, TYPE, COLR, POS, DIRN, ATT, 0.0, 0.0)
      END

      SUBROUTINE PROPS(AMB, DIF, SPEC, SPEXP, TRANSP, REFR)
C     Front and back area properties alike, white specular colour.
      REAL AMB, DIF, SPEC, SPEXP, TRANSP, REFR
      REAL WHITE(3)
      DATA WHITE /1.0, 1.0, 1.0/
      CALL GSAPR(AMB, DIF, SPEC, WHITE, SPEXP, TRANSP, REFR)
      CALL GSBAPR(AMB, DIF, SPEC, WHITE, SPEXP, TRANSP, REFR)
      END

      SUBROUTINE QUAD(PX, PY, PZ, UX, UY, UZ, VX, VY, VZ)
C     Parallelogram P, P+U, P+U+V, P+V (front side: normal U x V).
      REAL PX, PY, PZ, UX, UY, UZ, VX, VY, VZ
      REAL X(4), Y(4), Z(4)
      X(1) = PX
      Y(1) = PY
      Z(1) = PZ
      X(2) = PX + UX
      Y(2) = PY + UY
      Z(2) = PZ + UZ
      X(3) = (PX + UX) + VX
      Y(3) = (PY + UY) + VY
      Z(3) = (PZ + UZ) + VZ
      X(4) = PX + VX
      Y(4) = PY + VY
      Z(4) = PZ + VZ
      CALL GFA3(4, X, Y, Z)
      END

      SUBROUTINE BOARD
C     8 x 8 squares of side 0.1 in the plane y = 0.1, colours 8 and 9.
      INTEGER I, K
      REAL S
      PARAMETER (S=0.1)
      DO 20 I = 0, 7
         DO 10 K = 0, 7
            IF (MOD(I + K, 2) .EQ. 1) THEN
               CALL GSFACI(9)
            ELSE
               CALL GSFACI(8)
            END IF
            CALL QUAD(0.1 + REAL(I) * S, 0.1, 0.1 + REAL(K) * S,
     +                S, 0.0, 0.0, 0.0, 0.0, S)
   10    CONTINUE
   20 CONTINUE
      END

      SUBROUTINE SCNBRD(LIT)
C     Fig. 2/3: board, a mirror standing at its back, a red tile
C     floating above it and a glass block (refraction index 1.5); lit
C     (Fig. 3) or in flat colours, without the lighting model (Fig. 2).
      LOGICAL LIT
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      REAL X0, Y0, Z0, A, H
      PARAMETER (X0=0.55, Y0=0.102, Z0=0.5, A=0.2, H=0.12)
      IF (LIT) THEN
         CALL GSRFEQ(GRAMDS)
         CALL GSBRFQ(GRAMDS)
      ELSE
         CALL GSRFEQ(GRNONE)
         CALL GSBRFQ(GRNONE)
      END IF
      CALL PROPS(1.0, 0.85, 0.1, 10.0, 0.0, 1.0)
      CALL BOARD
      CALL PROPS(0.2, 0.2, 0.8, 50.0, 0.0, 1.0)
      CALL GSFACI(10)
      CALL QUAD(0.2, 0.1, 0.15, 0.6, 0.0, 0.0, 0.0, 0.5, 0.0)
      CALL PROPS(1.0, 0.85, 0.1, 10.0, 0.0, 1.0)
      CALL GSFACI(2)
      CALL QUAD(0.3, 0.35, 0.45, 0.15, 0.0, 0.0, 0.0, 0.02, 0.15)
C     the glass block, faces with outward normals
      CALL PROPS(0.1, 0.1, 0.2, 80.0, 0.85, 1.5)
      CALL GSFACI(11)
      CALL QUAD(X0, Y0, Z0, A, 0.0, 0.0, 0.0, 0.0, A)
      CALL QUAD(X0, Y0 + H, Z0, 0.0, 0.0, A, A, 0.0, 0.0)
      CALL QUAD(X0, Y0, Z0 + A, A, 0.0, 0.0, 0.0, H, 0.0)
      CALL QUAD(X0, Y0, Z0, 0.0, H, 0.0, A, 0.0, 0.0)
      CALL QUAD(X0 + A, Y0, Z0, 0.0, H, 0.0, 0.0, 0.0, A)
      CALL QUAD(X0, Y0, Z0, 0.0, 0.0, A, 0.0, H, 0.0)
      END

      SUBROUTINE SCNFAN
C     Fig. 4/5: board and a horizontal ventilator above it: five
C     blades (quadrilaterals from radius R0 to R1, corner directions
C     tabulated as cosine and sine) and a hexagonal hub.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      REAL CX, CY, CZ, R0, R1
      PARAMETER (CX=0.5, CY=0.55, CZ=0.5, R0=0.06, R1=0.34)
      REAL DIR(2,4,5), HUB(2,6), X(6), Y(6), Z(6), R
      INTEGER I, K
      DATA DIR /0.9993908, -0.0348995, 0.9271839, 0.3746066,
     +          0.8660254, 0.5000000, 0.9848078, -0.1736482,
     +          0.3420201, 0.9396926, -0.0697565, 0.9975641,
     +          -0.2079117, 0.9781476, 0.4694716, 0.8829476,
     +          -0.7880108, 0.6156615, -0.9702957, 0.2419219,
     +          -0.9945219, 0.1045285, -0.6946584, 0.7193398,
     +          -0.8290376, -0.5591929, -0.5299193, -0.8480481,
     +          -0.4067366, -0.9135455, -0.8987940, -0.4383711,
     +          0.2756374, -0.9612617, 0.6427876, -0.7660444,
     +          0.7431448, -0.6691306, 0.1391731, -0.9902681/
      DATA HUB /1.0, 0.0, 0.5, 0.8660254, -0.5, 0.8660254,
     +          -1.0, 0.0, -0.5, -0.8660254, 0.5, -0.8660254/
      CALL GSRFEQ(GRAMBD)
      CALL GSBRFQ(GRAMBD)
      CALL PROPS(1.0, 0.85, 0.0, 1.0, 0.0, 1.0)
      CALL BOARD
      CALL PROPS(0.9, 0.8, 0.0, 1.0, 0.0, 1.0)
      CALL GSFACI(12)
      DO 20 I = 1, 5
         DO 10 K = 1, 4
            IF (K .LE. 2) THEN
               R = R0
            ELSE
               R = R1
            END IF
            X(K) = CX + R * DIR(1, K, I)
            Y(K) = CY
            Z(K) = CZ + R * DIR(2, K, I)
   10    CONTINUE
         CALL GFA3(4, X, Y, Z)
   20 CONTINUE
      CALL GSFACI(13)
      DO 30 K = 1, 6
         X(K) = CX + R0 * HUB(1, K)
         Y(K) = CY + 0.004
         Z(K) = CZ + R0 * HUB(2, K)
   30 CONTINUE
      CALL GFA3(6, X, Y, Z)
      END

      INTEGER FUNCTION NBLEN(S)
C     Length of S without trailing blanks.
      CHARACTER*(*) S
      DO 10 NBLEN = LEN(S), 1, -1
         IF (S(NBLEN:NBLEN) .NE. ' ') RETURN
   10 CONTINUE
      NBLEN = 0
      END

      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
C     The programs' own ERROR HANDLING (replaces the library's): it
C     remembers the last error, counts and logs every error except 511
C     from SET HLHSR MODE (mode not available: the preview is skipped).
      INTEGER ERRNR, FCTID, ERRFIL
      INCLUDE 'GKSE_PAR'
      INTEGER LASTE, NERRS
      COMMON /FIGERR/ LASTE, NERRS
      LASTE = ERRNR
      IF (ERRNR .EQ. 511 .AND. FCTID .EQ. ESHRM) RETURN
      NERRS = NERRS + 1
      CALL GERLOG(ERRNR, FCTID, ERRFIL)
      END
