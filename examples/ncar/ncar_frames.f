C     SPDX-License-Identifier: MIT
C     ncar_frames.f -- as ncar_frames.c, in the style of NCAR's Fortran
C     examples: CALL FRAME after each picture, unit 2 as connection
C     identifier; gives gks2.png and gks2-002.png. Prints NCAR SHIM OK.
      PROGRAM NCARFR
      REAL X(2), Y(2)
      LOGICAL E1, E2, E3
      DATA X /0.1, 0.9/, Y /0.1, 0.9/
      OPEN (UNIT=31, FILE='gks2.png')
      CLOSE (31, STATUS='DELETE')
      OPEN (UNIT=31, FILE='gks2-002.png')
      CLOSE (31, STATUS='DELETE')
      CALL GOPKS(6, 0)
      CALL GOPWK(1, 2, 100)
      CALL GACWK(1)
      CALL GPL(2, X, Y)
      CALL FRAME
      Y(1) = 0.9
      Y(2) = 0.1
      CALL GPL(2, X, Y)
      CALL FRAME
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      INQUIRE (FILE='gks2.png', EXIST=E1)
      INQUIRE (FILE='gks2-002.png', EXIST=E2)
      INQUIRE (FILE='gks2-003.png', EXIST=E3)
      IF (E1 .AND. E2 .AND. .NOT. E3) THEN
        WRITE (*, '(A)') 'NCAR SHIM OK'
      ELSE
        WRITE (*, '(A)') 'NCAR SHIM FAILED'
      END IF
      END
