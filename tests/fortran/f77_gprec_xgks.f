C     SPDX-License-Identifier: MIT
      SUBROUTINE XGKSPR(IL, IA, MLDR, IERR, LDR, DATREC)
!     GPREC called as xgks's gksdemo.f calls it: SL = 0 with CHARACTER
!     actual arguments for LSTR and STR (a file of its own: gfortran
!     checks argument types between the calls within one file).
      INTEGER IL, IA(*), MLDR, IERR, LDR
      CHARACTER*80 DATREC(*)
      REAL EMPTRP(1)
      CHARACTER*1 DUMMYA(10), CH
      DATA EMPTRP /0.0/, CH /' '/, DUMMYA /10*' '/
      CALL GPREC(IL, IA, 0, EMPTRP, 0, DUMMYA, CH, MLDR, IERR, LDR,
     +   DATREC)
      END
