C     SPDX-License-Identifier: MIT
      PROGRAM FIG5
C     Fig. 5: as Fig. 4 with secondary rays clipped (ESCAPE GESRCS):
C     no shadow from the clipped part.
C     Usage: fig5_f77 [SIZE [PREFIX]]; writes PREFIXfig5.png and the
C     previews PREFIXfig5_none/hiddenline/zbuffer/painter.png.
C     C twin: examples/c/fig5.c (byte-identical pictures).
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      CALL FIGRUN('fig5', 2, GHRAYT, 1)
      END
