C     SPDX-License-Identifier: MIT
      SUBROUTINE GKUNAM(IUNIT, NAME, NLEN)
C     The name of the file the program OPENed unit IUNIT on, for GOPWK
C     (a unit number as connection identifier). NLEN = 0 when the unit
C     is not open, has no name or cannot be inquired. Only INQUIRE: the
C     program's unit is neither opened, closed nor positioned here.
      INTEGER IUNIT, NLEN
      CHARACTER*(*) NAME
      LOGICAL OP, NMD
      INTEGER IOS, I
      NLEN = 0
      NAME = ' '
      IF (IUNIT .LT. 0) RETURN
      OP = .FALSE.
      NMD = .FALSE.
      INQUIRE (UNIT=IUNIT, OPENED=OP, NAMED=NMD, NAME=NAME, IOSTAT=IOS)
      IF (IOS .NE. 0 .OR. .NOT. OP .OR. .NOT. NMD) RETURN
      DO 10 I = LEN(NAME), 1, -1
        IF (NAME(I:I) .NE. ' ') THEN
          NLEN = I
          RETURN
        END IF
   10 CONTINUE
      END
