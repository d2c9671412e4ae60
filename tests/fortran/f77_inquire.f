C     SPDX-License-Identifier: MIT
      PROGRAM INQ
!     List inquiry semantics (N = 0 count, 1-based N, out of range
!     2002) and the other wrappers' argument conversion.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INTEGER NFAIL, IERR, NUM, ITYP, IOL, IWK, I1, I2, I3, I4, NTYP
      REAL W(4), V(4), R1, R2, R3, CW(4), RV(4), CV(4)
      CHARACTER*80 IDR(3), ODR(1)
      LOGICAL EX
      NFAIL = 0
      CALL GQOPS(I1)
      CALL CHKI('GQOPS closed', I1, GGKCL, NFAIL)
      CALL GQEWK(0, IERR, NUM, ITYP)
      CALL CHKI('GQEWK closed errind', IERR, 8, NFAIL)
      CALL GOPKS(6, -1)
      CALL GQOPS(I1)
      CALL CHKI('GQOPS open', I1, GGKOP, NFAIL)
      CALL GQLVKS(IERR, I1)
      CALL CHKI('GQLVKS errind', IERR, 0, NFAIL)
      CALL CHKI('GQLVKS level', I1, GL2C, NFAIL)
!     available workstation types: 99, 100, 101, 3 (WISS), 2 (MO), 4 (MI)
!     and 210 (X11) in builds with GKS_WITH_X11, 102 last (NTYP)
      CALL GQWKCA(210, IERR, I1)
      NTYP = 7
      IF (IERR .EQ. 0) NTYP = 8
!     and 110-113 (PDF, SVG, PS, EPS) after MI in builds with cairo
      CALL GQWKCA(GWSPDF, IERR, I1)
      IF (IERR .EQ. 0) NTYP = NTYP + 4
      IF (IERR .EQ. 0) THEN
         CALL GQEWK(7, IERR, I1, ITYP)
         CALL CHKI('GQEWK(7) PDF', ITYP, GWSPDF, NFAIL)
         CALL GQEWK(10, IERR, I1, ITYP)
         CALL CHKI('GQEWK(10) EPS', ITYP, GWSEPS, NFAIL)
      END IF
      ITYP = -7
      CALL GQEWK(0, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(0) errind', IERR, 0, NFAIL)
      CALL CHKI('GQEWK(0) number', NUM, NTYP, NFAIL)
      CALL CHKI('GQEWK(0) untouched', ITYP, -7, NFAIL)
      CALL GQEWK(1, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(1)', ITYP, GWSNUL, NFAIL)
      CALL GQEWK(3, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(3) errind', IERR, 0, NFAIL)
      CALL CHKI('GQEWK(3)', ITYP, GWSPLG, NFAIL)
      CALL GQEWK(4, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(4) WISS', ITYP, 3, NFAIL)
      CALL GQEWK(5, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(5) MO', ITYP, GWSMO, NFAIL)
      CALL GQEWK(6, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(6) MI', ITYP, GWSMI, NFAIL)
      CALL GQEWK(NTYP, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(NTYP) PNG output', ITYP, GWSPNO, NFAIL)
      CALL GQEWK(NTYP + 1, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(7) errind', IERR, 2002, NFAIL)
      CALL CHKI('GQEWK(7) number', NUM, NTYP, NFAIL)
      CALL GQEWK(-1, IERR, NUM, ITYP)
      CALL CHKI('GQEWK(-1) errind', IERR, 2002, NFAIL)
!     open workstations 7 (CONID 5) and 3, activate 3
      CALL GQOPWK(0, IERR, IOL, IWK)
      CALL CHKI('GQOPWK none errind', IERR, 0, NFAIL)
      CALL CHKI('GQOPWK none count', IOL, 0, NFAIL)
      CALL GQOPWK(1, IERR, IOL, IWK)
      CALL CHKI('GQOPWK none (1)', IERR, 2002, NFAIL)
      CALL GOPWK(7, 5, GWSNUL)
      CALL GOPWK(3, 4, GWSPNG)
      CALL GACWK(3)
      CALL GQOPWK(0, IERR, IOL, IWK)
      CALL CHKI('GQOPWK count', IOL, 2, NFAIL)
      CALL GQOPWK(1, IERR, IOL, I1)
      CALL GQOPWK(2, IERR, IOL, I2)
      CALL CHKI('GQOPWK(2) errind', IERR, 0, NFAIL)
      CALL CHKI('GQOPWK set', I1 * I2 + I1 + I2, 31, NFAIL)
      CALL GQOPWK(3, IERR, IOL, IWK)
      CALL CHKI('GQOPWK(3) errind', IERR, 2002, NFAIL)
      CALL GQACWK(0, IERR, IOL, IWK)
      CALL CHKI('GQACWK count', IOL, 1, NFAIL)
      CALL GQACWK(1, IERR, IOL, IWK)
      CALL CHKI('GQACWK(1)', IWK, 3, NFAIL)
      CALL GQACWK(2, IERR, IOL, IWK)
      CALL CHKI('GQACWK(2) errind', IERR, 2002, NFAIL)
!     workstation inquiries
      CALL GQWKC(7, IERR, I1, I2)
      CALL CHKI('GQWKC errind', IERR, 0, NFAIL)
      CALL CHKI('GQWKC conid', I1, 5, NFAIL)
      CALL CHKI('GQWKC wtype', I2, GWSNUL, NFAIL)
      CALL GQWKC(8, IERR, I1, I2)
      CALL CHKI('GQWKC unopened', IERR, 25, NFAIL)
      CALL GQWKS(3, IERR, I1)
      CALL CHKI('GQWKS 3', I1, GACTIV, NFAIL)
      CALL GQWKS(7, IERR, I1)
      CALL CHKI('GQWKS 7', I1, GINACT, NFAIL)
      CALL GQWKCA(GWSPNG, IERR, I1)
      CALL CHKI('GQWKCA', I1, GOUTIN, NFAIL)
      CALL GQWKCL(GWSPNG, IERR, I1)
      CALL CHKI('GQWKCL', I1, GRASTR, NFAIL)
      CALL GQDSP(GWSPNG, IERR, I1, R1, R2, I2, I3)
      CALL CHKI('GQDSP errind', IERR, 0, NFAIL)
      CALL CHKI('GQDSP LX', I2, 1024, NFAIL)
      CALL CHKI('GQDSP LY', I3, 1024, NFAIL)
      CALL GQDSP(GWSPLG, IERR, I1, R1, R2, I2, I3)
      CALL CHKI('GQDSP large LX', I2, 8192, NFAIL)
      CALL GQWKM(IERR, I1, I2, I3)
      CALL CHKI('GQWKM errind', IERR, 0, NFAIL)
      IF (I1 .LT. 2 .OR. I2 .LT. 1) NFAIL = NFAIL + 1
      CALL GQMNTN(IERR, I1)
      CALL CHKI('GQMNTN errind', IERR, 0, NFAIL)
      IF (I1 .LT. 1) NFAIL = NFAIL + 1
      CALL GSDS(3, GBNIL, GALLOW)
      CALL GQWKDU(3, IERR, I1, I2, I3, I4)
      CALL CHKI('GQWKDU errind', IERR, 0, NFAIL)
      CALL CHKI('GQWKDU defmod', I1, GBNIL, NFAIL)
      CALL CHKI('GQWKDU regmod', I2, GALLOW, NFAIL)
!     colour representation
      CALL GSCR(3, 2, 0.25, 0.5, 0.75)
      CALL GQCR(3, 2, GSET, IERR, R1, R2, R3)
      CALL CHKI('GQCR errind', IERR, 0, NFAIL)
      CALL CHKR('GQCR red', R1, 0.25, NFAIL)
      CALL CHKR('GQCR green', R2, 0.5, NFAIL)
      CALL CHKR('GQCR blue', R3, 0.75, NFAIL)
      CALL GQCR(3, 2, 9, IERR, R1, R2, R3)
      CALL CHKI('GQCR bad type', IERR, 2000, NFAIL)
!     normalization transformation and clipping
      CALL GSWN(2, -1.0, 3.0, 10.0, 20.0)
      CALL GSVP(2, 0.125, 0.5, 0.25, 0.75)
      CALL GSELNT(2)
      CALL GQCNTN(IERR, I1)
      CALL CHKI('GQCNTN', I1, 2, NFAIL)
      CALL GQNT(2, IERR, W, V)
      CALL CHKI('GQNT errind', IERR, 0, NFAIL)
      CALL CHKR('GQNT xmin', W(1), -1.0, NFAIL)
      CALL CHKR('GQNT xmax', W(2), 3.0, NFAIL)
      CALL CHKR('GQNT ymin', W(3), 10.0, NFAIL)
      CALL CHKR('GQNT ymax', W(4), 20.0, NFAIL)
      CALL CHKR('GQNT vxmin', V(1), 0.125, NFAIL)
      CALL CHKR('GQNT vymax', V(4), 0.75, NFAIL)
      CALL GSCLIP(GNCLIP)
      CALL GQCLIP(IERR, I1, W)
      CALL CHKI('GQCLIP', I1, GNCLIP, NFAIL)
      CALL CHKR('GQCLIP rect', W(2), 0.5, NFAIL)
      CALL GSPLCI(5)
      CALL GSFACI(6)
      CALL GQPLCI(IERR, I1)
      CALL CHKI('GQPLCI', I1, 5, NFAIL)
      CALL GQFACI(IERR, I1)
      CALL CHKI('GQFACI', I1, 6, NFAIL)
      CALL GSWKWN(3, 0.0, 0.5, 0.0, 0.5)
      CALL GSWKVP(3, 0.0, 256.0, 0.0, 128.0)
      CALL GQWKT(3, IERR, I1, W, CW, RV, CV)
      CALL CHKI('GQWKT errind', IERR, 0, NFAIL)
      CALL CHKR('GQWKT req win', W(2), 0.5, NFAIL)
      CALL CHKR('GQWKT req vp', RV(2), 256.0, NFAIL)
      CALL CHKR('GQWKT req vp y', RV(4), 128.0, NFAIL)
!     MESSAGE (full and subset form) and ESCAPE set-file-name
      CALL GMSG(7, 'hello   ')
      CALL GMSGS(7, 3, 'abcdef')
      WRITE (IDR(1), '(I10)') 3
      IDR(2) = 'f77_'
      IDR(3) = 'esc   '
      CALL GESC(GESSFN, 3, IDR, 1, I1, ODR)
      CALL CHKI('GESC LODR', I1, 0, NFAIL)
      CALL GCLRWK(3, GALWAY)
      CALL GUWK(3, GPERFO)
      CALL GRSGWK(3)
      CALL GDAWK(3)
      CALL GCLWK(3)
      CALL GCLWK(7)
      CALL GCLKS
      INQUIRE (FILE='f77_esc.png', EXIST=EX)
      IF (.NOT. EX) THEN
         WRITE (*, '(A)') 'GESC: f77_esc.png not written'
         NFAIL = NFAIL + 1
      END IF
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 INQUIRE PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 INQUIRE FAIL ', NFAIL
         STOP 1
      END IF
      END
