C     SPDX-License-Identifier: MIT
      PROGRAM ATTRS
!     Output primitives, attributes, representations and their
!     inquiries through the FORTRAN 77 binding (gks_fortran_output.c).
!     Errors are caught by this program's own GERHND (COMMON /ERRS/).
!     Prints F77 ATTRS PASS or the failing checks.
      IMPLICIT NONE
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INCLUDE 'GKSE_PAR'
      INTEGER LASTER, LASTF, NERR
      COMMON /ERRS/ LASTER, LASTF, NERR
      INTEGER NFAIL, ERR, I, J, K, M, N, LASF(17), LGOT(17)
      INTEGER PTR(2), COLIA(3,2), PARR(4,4), NLT, LT, NLW, NPP
      INTEGER FONT, PREC, NCHH, NCHX, NIS, IS, NHS, HS
      INTEGER MPL, MPM, MTX, MFA, MPA, MCOL, OL
      REAL X, Y, R1, R2, R3, CPX, CPY, TX(4), TY(4)
      REAL PX(8), PY(8), PZ(8), TDX(2), TDY(2), TDZ(2)
      DATA PX /0.1, 0.9, 0.9, 0.1, 0.4, 0.6, 0.6, 0.4/
      DATA PY /0.1, 0.1, 0.9, 0.9, 0.4, 0.4, 0.6, 0.6/
      DATA PZ /8*0.5/
      DATA PTR /4, 8/
      DATA COLIA /1, 2, 3, 4, 5, 6/
      DATA TDX /1.0, 0.0/, TDY /0.0, 0.0/, TDZ /0.0, 1.0/
      NFAIL = 0
      NERR = 0
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 0, GWSNUL)
      CALL GACWK(1)
!     Individual attributes: set, inquire.
      CALL GSLN(GLDASH)
      CALL GQLN(ERR, I)
      CALL CHKI('GQLN', I, GLDASH, NFAIL)
      CALL GSLWSC(2.5)
      CALL GQLWSC(ERR, X)
      CALL CHKR('GQLWSC', X, 2.5, NFAIL)
      CALL GSMK(GOMARK)
      CALL GQMK(ERR, I)
      CALL CHKI('GQMK', I, GOMARK, NFAIL)
      CALL GSMKSC(3.0)
      CALL GQMKSC(ERR, X)
      CALL CHKR('GQMKSC', X, 3.0, NFAIL)
      CALL GSPMCI(4)
      CALL GQPMCI(ERR, I)
      CALL CHKI('GQPMCI', I, 4, NFAIL)
      CALL GSTXFP(1, GSTRKP)
      CALL GQTXFP(ERR, FONT, PREC)
      CALL CHKI('GQTXFP font', FONT, 1, NFAIL)
      CALL CHKI('GQTXFP prec', PREC, GSTRKP, NFAIL)
      CALL GSCHH(0.05)
      CALL GQCHH(ERR, X)
      CALL CHKR('GQCHH', X, 0.05, NFAIL)
      CALL GSCHXP(1.5)
      CALL GQCHXP(ERR, X)
      CALL CHKR('GQCHXP', X, 1.5, NFAIL)
      CALL GSCHSP(0.25)
      CALL GQCHSP(ERR, X)
      CALL CHKR('GQCHSP', X, 0.25, NFAIL)
      CALL GSCHUP(-1.0, 0.0)
      CALL GQCHUP(ERR, X, Y)
      CALL CHKR('GQCHUP x', X, -1.0, NFAIL)
      CALL GQCHB(ERR, X, Y)
      CALL CHKR('GQCHB x', X, 0.0, NFAIL)
      CALL CHKR('GQCHB y', Y, 1.0, NFAIL)
      CALL GSCHUP(0.0, 1.0)
      CALL GSTXP(GUP)
      CALL GQTXP(ERR, I)
      CALL CHKI('GQTXP', I, GUP, NFAIL)
      CALL GSTXP(GRIGHT)
      CALL GSTXAL(GACENT, GAHALF)
      CALL GQTXAL(ERR, I, J)
      CALL CHKI('GQTXAL h', I, GACENT, NFAIL)
      CALL CHKI('GQTXAL v', J, GAHALF, NFAIL)
      CALL GSTXAL(GAHNOR, GAVNOR)
      CALL GSFAIS(GHATCH)
      CALL GQFAIS(ERR, I)
      CALL CHKI('GQFAIS', I, GHATCH, NFAIL)
      CALL GSFASI(-3)
      CALL GQFASI(ERR, I)
      CALL CHKI('GQFASI', I, -3, NFAIL)
      CALL GSPA(0.1, 0.2)
      CALL GQPA(ERR, R1, R2, R3, X)
      CALL CHKR('GQPA pwx', R1, 0.1, NFAIL)
      CALL CHKR('GQPA phy', X, 0.2, NFAIL)
      CALL GSPARF(0.3, 0.4)
      CALL GQPARF(ERR, X, Y)
      CALL CHKR('GQPARF y', Y, 0.4, NFAIL)
      CALL GSPKID(9)
      CALL GQPKID(ERR, I)
      CALL CHKI('GQPKID', I, 9, NFAIL)
      CALL GSEDFG(1)
      CALL GQEDFG(ERR, I)
      CALL CHKI('GQEDFG', I, 1, NFAIL)
      CALL GSEDT(3)
      CALL GQEDT(ERR, I)
      CALL CHKI('GQEDT', I, 3, NFAIL)
      CALL GSEWSC(2.0)
      CALL GQEWSC(ERR, X)
      CALL CHKR('GQEWSC', X, 2.0, NFAIL)
      CALL GSEDI(2)
      CALL GQEDI(ERR, I)
      CALL CHKI('GQEDI', I, 2, NFAIL)
!     Aspect source flags: 13 (GSASF) and 17 (GASF3).
      DO 10 I = 1, 17
         LASF(I) = MOD(I, 2)
   10 CONTINUE
      CALL GASF3(LASF)
      CALL GQASF3(ERR, LGOT)
      DO 20 I = 1, 17
         CALL CHKI('GQASF3', LGOT(I), LASF(I), NFAIL)
   20 CONTINUE
      DO 30 I = 1, 13
         LASF(I) = GINDIV
   30 CONTINUE
      CALL GSASF(LASF)
      CALL GQASF(ERR, LGOT)
      CALL CHKI('GQASF 13', LGOT(13), GINDIV, NFAIL)
!     Argument errors reach GERHND with the function identification.
      CALL GSCHH(0.0)
      CALL CHKI('GSCHH 0 error', LASTER, 78, NFAIL)
      CALL CHKI('GSCHH 0 fct', LASTF, ESCHH, NFAIL)
      CALL GSEDI(0)
      CALL CHKI('GSEDI 0 error', LASTER, 500, NFAIL)
!     Representations: SET and REALIZED values.
      CALL GSPLR(1, 6, GLDOT, 500.0, 300)
      CALL GQPLR(1, 6, GSET, ERR, I, X, J)
      CALL CHKI('GQPLR err', ERR, 0, NFAIL)
      CALL CHKI('GQPLR type', I, GLDOT, NFAIL)
      CALL CHKR('GQPLR width', X, 500.0, NFAIL)
      CALL CHKI('GQPLR colour', J, 300, NFAIL)
      CALL GQPLR(1, 6, GREALI, ERR, I, X, J)
      CALL CHKR('GQPLR realized width', X, 256.0, NFAIL)
      CALL CHKI('GQPLR realized colour', J, 1, NFAIL)
      CALL GSTXR(1, 2, 1, GCHARP, 0.5, 0.1, 1)
      CALL GQTXR(1, 2, GSET, ERR, FONT, PREC, X, Y, I)
      CALL CHKI('GQTXR prec', PREC, GCHARP, NFAIL)
      CALL CHKR('GQTXR chsp', Y, 0.1, NFAIL)
      CALL GSFAR(1, 3, GHATCH, -2, 1)
      CALL GQFAR(1, 3, GSET, ERR, I, J, K)
      CALL CHKI('GQFAR style', J, -2, NFAIL)
      CALL GSEDR(1, 4, 1, 2, 1.5, 1)
      CALL GQEDR(1, 4, GSET, ERR, I, J, X, K)
      CALL CHKI('GQEDR type', J, 2, NFAIL)
      CALL CHKR('GQEDR width', X, 1.5, NFAIL)
!     Pattern from the 2x2 sub-array at column 2, row 1 of COLIA(3,2).
      CALL GSPAR(1, 5, 3, 2, 2, 1, 2, 2, COLIA)
      CALL GQPAR(1, 5, GSET, 4, 4, ERR, N, M, PARR)
      CALL CHKI('GQPAR err', ERR, 0, NFAIL)
      CALL CHKI('GQPAR n', N, 2, NFAIL)
      CALL CHKI('GQPAR m', M, 2, NFAIL)
      CALL CHKI('GQPAR (1,1)', PARR(1,1), 2, NFAIL)
      CALL CHKI('GQPAR (2,2)', PARR(2,2), 6, NFAIL)
      CALL GQEPLI(1, 0, ERR, OL, I)
      CALL CHKI('GQEPLI count', OL, 6, NFAIL)
      CALL GQEPLI(1, 6, ERR, OL, I)
      CALL CHKI('GQEPLI 6th', I, 6, NFAIL)
!     Workstation description table.
      CALL GQPLF(GWSPNG, 2, ERR, NLT, LT, NLW, X, R1, R2, NPP)
      CALL CHKI('GQPLF err', ERR, 0, NFAIL)
      CALL CHKI('GQPLF nlt', NLT, 4, NFAIL)
      CALL CHKI('GQPLF lt', LT, 2, NFAIL)
      CALL CHKI('GQPLF nppli', NPP, 5, NFAIL)
      CALL GQTXF(GWSPNG, 3, ERR, N, FONT, PREC, NCHH, X, Y, NCHX, R1,
     +           R2, NPP)
      CALL CHKI('GQTXF n', N, 9, NFAIL)
      CALL CHKI('GQTXF prec', PREC, GSTRKP, NFAIL)
      CALL GQFAF(GWSPNG, 2, 12, ERR, NIS, IS, NHS, HS, NPP)
      CALL CHKI('GQFAF err', ERR, 0, NFAIL)
      CALL CHKI('GQFAF is', IS, GSOLID, NFAIL)
      CALL CHKI('GQFAF hs', HS, -12, NFAIL)
      CALL CHKI('GQFAF nhs', NHS, 12, NFAIL)
      CALL GQPPLR(GWSPNG, 2, ERR, I, X, J)
      CALL CHKI('GQPPLR type', I, GLDASH, NFAIL)
      CALL GQPPLR(GWSPNG, 9, ERR, I, X, J)
      CALL CHKI('GQPPLR 9', ERR, 62, NFAIL)
      CALL GQLWK(GWSPNG, ERR, MPL, MPM, MTX, MFA, MPA, MCOL)
      CALL CHKI('GQLWK mcoli', MCOL, 256, NFAIL)
      CALL GQPPAR(GWSPNG, 1, 4, 4, ERR, N, M, PARR)
      CALL CHKI('GQPPAR n', N, 2, NFAIL)
!     Primitives: no errors expected.
      NERR = 0
      CALL GPM(4, PX, PY)
      CALL GPM3(4, PX, PY, PZ)
      CALL GTX(0.5, 0.5, 'GKS   ')
      CALL GTXS(0.5, 0.5, 3, 'GKS-3D')
      CALL GTX3(0.5, 0.5, 0.5, TDX, TDY, TDZ, 'TEXT 3')
      CALL GFAS(2, PTR, PX, PY)
      CALL GFAS3(2, PTR, PX, PY, PZ)
      CALL GCA(0.1, 0.1, 0.9, 0.9, 3, 2, 1, 1, 3, 2, COLIA)
      CALL GCA3(0.1, 0.1, 0.0, 0.9, 0.9, 0.0, 0.9, 0.1, 0.0, 3, 2, 1,
     +          1, 3, 2, COLIA)
      CALL CHKI('primitive errors', NERR, 0, NFAIL)
!     Primitive errors: too few points, bad sub-array, GDP, bad text.
      CALL GPM(0, PX, PY)
      CALL CHKI('GPM 0', LASTER, 100, NFAIL)
      CALL CHKI('GPM 0 fct', LASTF, EPM, NFAIL)
      CALL GCA(0.1, 0.1, 0.9, 0.9, 3, 2, 2, 1, 3, 2, COLIA)
      CALL CHKI('GCA sub-array', LASTER, 91, NFAIL)
      CALL GGDP(2, PX, PY, 1, 0, ' ')
      CALL CHKI('GGDP', LASTER, 102, NFAIL)
      PTR(2) = 2
      CALL GFAS(2, PTR, PX, PY)
      CALL CHKI('GFAS PTR not ascending', LASTER, 100, NFAIL)
!     Text extent: LEFT/BASE alignment, concatenation point after 'AB'.
      CALL GSCHXP(1.0)
      CALL GSCHSP(0.0)
      CALL GQTXX(1, 0.2, 0.3, 'AB  ', ERR, CPX, CPY, TX, TY)
      CALL CHKI('GQTXX err', ERR, 0, NFAIL)
      CALL CHKR('GQTXX x1', TX(1), 0.2, NFAIL)
      CALL CHKR('GQTXX cpx', CPX, TX(2), NFAIL)
      CALL CHKR('GQTXX cpy', CPY, 0.3, NFAIL)
      R1 = TX(2) - TX(1)
      IF (R1 .LE. 0.05) THEN
         WRITE (*, '(A)') 'GQTXX: extent too narrow'
         NFAIL = NFAIL + 1
      END IF
!     Subset form with LSTR = 1: the extent of 'A' alone is narrower.
      CALL GQTXXS(1, 0.2, 0.3, 1, 'AB', ERR, CPX, CPY, TX, TY)
      IF (TX(2) - TX(1) .GE. R1 .OR. TX(2) - TX(1) .LE. 0.0) THEN
         WRITE (*, '(A)') 'GQTXXS: extent of A not narrower than AB'
         NFAIL = NFAIL + 1
      END IF
!     Derived stroke fonts (RAL GKS's numbers, docs/WORKSTATIONS.md):
!     bundles accept -104..-106, -103 reports 76; the bold -102 is one
!     font unit (1/21 of the height) wider per character ('AB  ': 4).
      LASTER = 0
      CALL GSTXR(1, 4, -104, GSTRKP, 1.0, 0.0, 1)
      CALL GSTXR(1, 5, -105, GSTRKP, 1.0, 0.0, 1)
      CALL GSTXR(1, 6, -106, GSTRKP, 1.0, 0.0, 1)
      CALL CHKI('GSTXR -104..-106', LASTER, 0, NFAIL)
      CALL GSTXR(1, 6, -103, GSTRKP, 1.0, 0.0, 1)
      CALL CHKI('GSTXR -103', LASTER, 76, NFAIL)
      CALL GQTXR(1, 5, GREALI, ERR, FONT, PREC, X, Y, I)
      CALL CHKI('GQTXR -105', FONT, -105, NFAIL)
      CALL GQTXF(GWSPNG, 9, ERR, N, FONT, PREC, NCHH, X, Y, NCHX, R1,
     +           R2, NPP)
      CALL CHKI('GQTXF 9th', FONT, -107, NFAIL)
      CALL GQCHH(ERR, R3)
      CALL GQTXX(1, 0.2, 0.3, 'AB  ', ERR, CPX, CPY, TX, TY)
      R1 = TX(2) - TX(1)
      CALL GSTXFP(-102, GSTRKP)
      CALL GQTXX(1, 0.2, 0.3, 'AB  ', ERR, CPX, CPY, TX, TY)
      CALL CHKR('GQTXX bold', TX(2) - TX(1), R1 + 4.0 * R3 / 21.0,
     +          NFAIL)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 ATTRS PASS'
      ELSE
         WRITE (*, '(A, I0, A)') 'F77 ATTRS ', NFAIL, ' checks failed'
      END IF
      END

      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
!     This program's ERROR HANDLING: remembers the last error.
      INTEGER ERRNR, FCTID, ERRFIL
      INTEGER LASTER, LASTF, NERR
      COMMON /ERRS/ LASTER, LASTF, NERR
      LASTER = ERRNR
      LASTF = FCTID
      IF (ERRFIL .LT. 0) LASTF = -1
      NERR = NERR + 1
      END
