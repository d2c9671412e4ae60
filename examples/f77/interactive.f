C     SPDX-License-Identifier: MIT
      PROGRAM INTACT
C     interactive.f -- the FORTRAN 77 twin of examples/c/interactive.c:
C     the Fig. 3 scene in a window (the X11 workstation, type 210) in
C     z-buffer preview. Click with mouse button 1 (LOCATOR 1 in EVENT
C     mode) to turn the camera: the horizontal position sets the
C     azimuth, the vertical one the elevation. Keys (CHOICE 1 in EVENT
C     mode): 1 ray trace the current view in the same window, 2 back to
C     the z-buffer preview, 0 quit. The scene is one segment, redrawn
C     with the new view by REDRAW ALL SEGMENTS ON WORKSTATION.
C     Usage: interactive_f77 [SCRIPT [png]] -- SCRIPT: an input script
C     (docs/INPUT.md) replayed instead of the mouse and keys; with png
C     on the PNG workstation (batch), one file interactive-NNN.png per
C     step. GET_COMMAND_ARGUMENT is the one Fortran 2003 intrinsic used.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER WS, IX11
      PARAMETER (WS=1, IX11=210)
      INTEGER LASTE, NERRS
      COMMON /FIGERR/ LASTE, NERRS
      INTEGER NARG, IERR, ISTATE, LODR, IWK, ICL, IDNR
      INTEGER ISTAT, ICH, ITNR, IFRAME, ACT(2), DEACT(1)
      LOGICAL PNG, DONE
      REAL AZ, EL, PI, PX, PY, TOUT
      REAL WHITE(3), ORIGIN(3), AMB(3), LAMP(3)
      CHARACTER*80 ARG, IDR(2), ODR(1)
      DATA WHITE /1.0, 1.0, 1.0/, ORIGIN /0.0, 0.0, 0.0/
      DATA AMB /0.25, 0.25, 0.25/, LAMP /0.2, 0.95, 0.85/
      DATA ACT /2, 3/, DEACT /0/
      PI = 4.0 * ATAN(1.0)
      NARG = COMMAND_ARGUMENT_COUNT()
      PNG = .FALSE.
      IF (NARG .GE. 2) THEN
         CALL GET_COMMAND_ARGUMENT(2, ARG)
         PNG = ARG .EQ. 'png'
      END IF
      CALL GOPKS(6, 0)
      IF (PNG) THEN
         CALL GOPWK(WS, 0, GWSPNG)
      ELSE
         CALL GOPWK(WS, 0, IX11)
      END IF
      CALL GQWKS(WS, IERR, ISTATE)
      IF (IERR .NE. 0) THEN
         WRITE (*, '(A)')
     +      'interactive: cannot open the workstation (no display?)'
         CALL GCLKS
         STOP 1
      END IF
      IF (NARG .GE. 1) THEN
C        ESCAPE input script: IDR(1) = workstation, IDR(2) = file
         CALL GET_COMMAND_ARGUMENT(1, ARG)
         WRITE (IDR(1), '(I10)') WS
         IDR(2) = ARG
         CALL GESC(GESISC, 2, IDR, 1, LODR, ODR)
      END IF
      IF (PNG) THEN
         WRITE (IDR(1), '(I10)') WS
         IDR(2) = 'interactive'
         CALL GESC(GESSFN, 2, IDR, 1, LODR, ODR)
      END IF
      CALL GACWK(WS)
      CALL GSWKWN(WS, 0.0, 1.0, 0.0, 1.0)
      CALL GSWKVP(WS, 0.0, 800.0, 0.0, 800.0)
C     The paper's camera: VPN (0.35, 0.55, 1).
      AZ = ATAN2(0.35, 1.0)
      EL = ATAN2(0.55, SQRT(0.35 * 0.35 + 1.0))
      CALL GSHRM(WS, GHZBUF)
      CALL GSCR(WS, 0, 0.1, 0.11, 0.14)
      CALL GSCR(WS, 2, 0.85, 0.15, 0.1)
      CALL GSCR(WS, 8, 0.9, 0.9, 0.85)
      CALL GSCR(WS, 9, 0.15, 0.2, 0.45)
      CALL GSCR(WS, 10, 0.75, 0.75, 0.8)
      CALL GSCR(WS, 11, 0.8, 0.95, 0.9)
      CALL GSCR(WS, 12, 0.9, 0.6, 0.15)
      CALL GSCR(WS, 13, 0.3, 0.3, 0.3)
      CALL VIEWAE(WS, AZ, EL)
      CALL LIGHT(WS, 2, GAMB, AMB, ORIGIN)
      CALL LIGHT(WS, 3, GPOSI, WHITE, LAMP)
      CALL GSVWI(1)
      CALL GSFAIS(GSOLID)
      CALL GSLSS(2, ACT, 0, DEACT)
C     2 x 2 samples per pixel when tracing
      WRITE (IDR(1), '(3I10)') WS, 4, 0
      CALL GESC(GESRSA, 1, IDR, 1, LODR, ODR)
      CALL GCRSG(1)
      CALL SCNBRD(.TRUE.)
      CALL GCLSG
      CALL GRSGWK(WS)
      CALL GUWK(WS, GPERFO)
      CALL GSLCM(WS, 1, GEVENT, GECHO)
      CALL GSCHM(WS, 1, GEVENT, GECHO)
      CALL GMSG(WS,
     +   'click: turn the camera; 1 ray trace, 2 z-buffer, 0 quit')
      TOUT = 60.0
      IF (PNG) TOUT = 0.0
      IFRAME = 0
      DONE = .FALSE.
   10 IF (DONE) GOTO 90
      CALL GWAIT(TOUT, IWK, ICL, IDNR)
      IF (ICL .EQ. GNCLAS) THEN
C        batch: the script is over
         DONE = PNG
         GOTO 10
      END IF
      IF (ICL .EQ. GLOCAT) THEN
         CALL GGTLC(ITNR, PX, PY)
C        NDC of the click: x -> azimuth in [-pi, pi], y -> elevation
C        in [5, 85] degrees
         AZ = (PX - 0.5) * 2.0 * PI
         EL = (5.0 + 80.0 * PY) * PI / 180.0
         CALL VIEWAE(WS, AZ, EL)
         WRITE (*, '(A, F6.1, A, F6.1, A)') 'view: azimuth',
     +      AZ * 180.0 / PI, ' elevation', EL * 180.0 / PI, ' deg'
      ELSE IF (ICL .EQ. GCHOIC) THEN
         CALL GGTCH(ISTAT, ICH)
         IF (ISTAT .NE. GOK .OR. ICH .EQ. 0 .OR. ICH .EQ. 9) THEN
            DONE = .TRUE.
            GOTO 10
         END IF
         IF (ICH .EQ. 1) THEN
            CALL GSHRM(WS, GHRAYT)
            WRITE (*, '(A)') 'HLHSR mode ray tracing'
         ELSE
            CALL GSHRM(WS, GHZBUF)
            WRITE (*, '(A)') 'HLHSR mode z-buffer'
         END IF
      END IF
      IF (PNG) THEN
C        batch: one file per step
         IFRAME = IFRAME + 1
         WRITE (IDR(1), '(I10)') WS
         WRITE (IDR(2), '(A, I3.3)') 'interactive-', IFRAME
         CALL GESC(GESSFN, 2, IDR, 1, LODR, ODR)
      END IF
C     the segment with the new view or HLHSR mode
      CALL GRSGWK(WS)
      CALL GUWK(WS, GPERFO)
      GOTO 10
   90 CALL GDAWK(WS)
      CALL GCLWK(WS)
      CALL GCLKS
      IF (NERRS .GT. 0) STOP 1
      END

      SUBROUTINE VIEWAE(WS, AZ, EL)
C     View 1 of figlib.f's VIEW with the view plane normal of azimuth
C     AZ and elevation EL (radians) around the y axis.
      INTEGER WS
      REAL AZ, EL
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER ERR
      REAL VWM(4,4), PRM(4,4), PRVP(6), CLIPB(6)
      DATA PRVP /0.0, 1.0, 0.0, 1.0, 0.0, 1.0/
      DATA CLIPB /0.0, 1.0, 0.0, 1.0, 0.0, 1.0/
      CALL GEVVWM(0.5, 0.3, 0.5, 0.0, 1.0, 0.0, COS(EL) * SIN(AZ),
     +            SIN(EL), COS(EL) * COS(AZ), GNDC, ERR, VWM)
      CALL GEVPJM(-0.55, 0.55, -0.55, 0.55, PRVP, GPERS,
     +            0.0, 0.0, 2.5, 0.0, -1.0, 1.0, ERR, PRM)
      CALL GSVWR(WS, 1, VWM, PRM, CLIPB, GCLIP, GCLIP, GCLIP)
      END
