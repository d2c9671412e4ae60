C     SPDX-License-Identifier: MIT
C     A Fortran unit as the connection identifier (issue 17 item 5): a
C     metafile workstation on a unit the program OPENed writes that
C     file, GQWKC answers the unit, the unit stays open and closing it
C     keeps the metafile;
C     an unopened unit keeps gksN.gksm. Run with GKS3D_WS_TYPES=41=100
C     and GKS3D_ASF=BUNDLED: a foreign type opens, the flags start
C     BUNDLED. Prints FAIL lines and ALL OK when none failed.
      PROGRAM F77UNI
      INCLUDE 'GKS_PAR'
      INTEGER NFAIL, IERR, ICON, ITYP, IDRL, I, LASF(17)
      LOGICAL OP, EX
      REAL XS(2), YS(2)
      NFAIL = 0
      XS(1) = 0.1
      XS(2) = 0.9
      YS(1) = 0.2
      YS(2) = 0.8
      OPEN (UNIT=11, FILE='f77_unit_mf.gksm', STATUS='UNKNOWN')
      CALL GOPKS(6, -1)
C     GKS3D_ASF=BUNDLED.
      CALL GQASF3(IERR, LASF)
      DO 10 I = 1, 17
        CALL CHKI('initial ASF', LASF(I), GBUNDL, NFAIL)
   10 CONTINUE
C     The metafile goes to the file unit 11 was opened on.
      CALL GOPWK(1, 11, 2)
      CALL GQWKC(1, IERR, ICON, ITYP)
      CALL CHKI('GQWKC errind', IERR, 0, NFAIL)
      CALL CHKI('GQWKC conid', ICON, 11, NFAIL)
      CALL CHKI('GQWKC type', ITYP, 2, NFAIL)
      CALL GACWK(1)
      CALL GPL(2, XS, YS)
      CALL GDAWK(1)
      CALL GCLWK(1)
      INQUIRE (FILE='gks11.gksm', EXIST=EX)
      IF (EX) THEN
        WRITE (*, *) 'FAIL gks11.gksm written'
        NFAIL = NFAIL + 1
      END IF
      INQUIRE (UNIT=11, OPENED=OP)
      IF (.NOT. OP) THEN
        WRITE (*, *) 'FAIL unit 11 closed by GKS'
        NFAIL = NFAIL + 1
      END IF
C     The program closes its unit (no truncation of what GKS wrote) and
C     reads the file back through another unit (MI).
      CLOSE (11)
      OPEN (UNIT=12, FILE='f77_unit_mf.gksm', STATUS='OLD')
      CALL GOPWK(2, 12, 4)
      CALL GGTITM(2, ITYP, IDRL)
      IF (ITYP .LE. 0) THEN
        WRITE (*, *) 'FAIL no item in f77_unit_mf.gksm', ITYP
        NFAIL = NFAIL + 1
      END IF
      CALL GCLWK(2)
      CLOSE (12)
C     A unit nobody opened: the decimal text (gks13.gksm).
      CALL GOPWK(3, 13, 2)
      CALL GQWKC(3, IERR, ICON, ITYP)
      CALL CHKI('GQWKC conid 13', ICON, 13, NFAIL)
      CALL GCLWK(3)
      INQUIRE (FILE='gks13.gksm', EXIST=EX)
      IF (.NOT. EX) THEN
        WRITE (*, *) 'FAIL gks13.gksm missing'
        NFAIL = NFAIL + 1
      END IF
C     The preconnected output unit is no file: a PNG workstation on
C     unit 6 keeps its usual frame names.
      CALL GOPWK(4, 6, 41)
      CALL GQWKC(4, IERR, ICON, ITYP)
      CALL CHKI('GQWKC foreign type errind', IERR, 0, NFAIL)
      CALL CHKI('GQWKC conid 6', ICON, 6, NFAIL)
      CALL CHKI('GQWKC type 41 -> 100', ITYP, 100, NFAIL)
      CALL GCLWK(4)
      CALL GCLKS
      IF (NFAIL .EQ. 0) WRITE (*, *) 'ALL OK'
      END

      SUBROUTINE CHKI(WHAT, IGOT, IWANT, NFAIL)
      CHARACTER*(*) WHAT
      INTEGER IGOT, IWANT, NFAIL
      IF (IGOT .NE. IWANT) THEN
        WRITE (*, *) 'FAIL ', WHAT, IGOT, IWANT
        NFAIL = NFAIL + 1
      END IF
      END
