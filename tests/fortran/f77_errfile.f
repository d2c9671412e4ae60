C     SPDX-License-Identifier: MIT
      PROGRAM ERRFIL
!     Provokes errors with the library's default GERHND/GERLOG writing
!     to unit 22; the C checker compares the file line by line.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      CHARACTER*80 IDR(1), ODR(1)
      OPEN (22, FILE='f77_errors.txt', STATUS='REPLACE')
      CALL GOPKS(22, -1)
      CALL GOPWK(1, 1, 12345)
      CALL GOPWK(1, 1, GWSNUL)
      CALL GACWK(5)
!     a file in a folder that does not exist (named by NCAR's -1391):
!     the line names the file and the system's reason
      IDR(1) = 'no_such_folder/f.png'
      CALL GESC(-1391, 1, IDR, 1, 1, ODR)
      CALL GOPWK(2, 1, GWSPNG)
      CALL GOPKS(22, -1)
      CALL GCLRWK(1, 7)
      CALL GCLWK(1)
      CALL GCLKS
      CLOSE (22)
      END
