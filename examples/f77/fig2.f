C     SPDX-License-Identifier: MIT
      PROGRAM FIG2
C     Fig. 2: the checkerboard scene drawn the conventional GKS way:
C     HLHSR mode z-buffer, no lighting model (flat colours).
C     Usage: fig2_f77 [SIZE [PREFIX]]; writes PREFIXfig2.png and the
C     previews PREFIXfig2_none/hiddenline/zbuffer/painter.png.
C     C twin: examples/c/fig2.c (byte-identical pictures).
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      CALL FIGRUN('fig2', 3, GHZBUF, 0)
      END
