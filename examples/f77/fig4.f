C     SPDX-License-Identifier: MIT
      PROGRAM FIG4
C     Fig. 4: the ventilator, its far half cut off by the view clip,
C     ray traced, secondary rays NOT clipped: it still casts its shadow.
C     Usage: fig4_f77 [SIZE [PREFIX]]; writes PREFIXfig4.png and the
C     previews PREFIXfig4_none/hiddenline/zbuffer/painter.png.
C     C twin: examples/c/fig4.c (byte-identical pictures).
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      CALL FIGRUN('fig4', 2, GHRAYT, 0)
      END
