C     SPDX-License-Identifier: MIT
      PROGRAM FIG3
C     Fig. 3: the same scene ray traced: positional light, shadows,
C     a mirror and a glass block.
C     Usage: fig3_f77 [SIZE [PREFIX]]; writes PREFIXfig3.png and the
C     previews PREFIXfig3_none/hiddenline/zbuffer/painter.png.
C     C twin: examples/c/fig3.c (byte-identical pictures).
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      CALL FIGRUN('fig3', 1, GHRAYT, 0)
      END
