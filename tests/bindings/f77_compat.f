C     SPDX-License-Identifier: MIT
C     Regression test of issue 17 items 3, 4, 5 and 9 and of the added
C     inquiries, through the FORTRAN 77 binding. Prints one line per
C     failed check and ALL OK at the end when none failed.
      PROGRAM F77CMP
      INCLUDE 'GKS_PAR'
      INTEGER NFAIL, IERR, NERR, LASTE, I1, I2, I3, LODR, IWK
      REAL CPX, CPY, TX1(4), TY1(4), TX2(4), TY2(4), R, G, B
      REAL VWM(4,4), XS(2), YS(2)
      LOGICAL EX1, EX2, EX3
      CHARACTER*80 IDR(2), ODR(1)
      COMMON /ERRS/ NERR, LASTE
      NFAIL = 0
      NERR = 0
      IWK = 1
      CALL GOPKS(6, -1)
      CALL GOPWK(IWK, 0, 100)
      CALL GACWK(IWK)
C     Item 3: text keeps its trailing blanks (the extent grows).
      CALL GSCHH(0.05)
      CALL GQTXX(IWK, 0.1, 0.5, 'AB', IERR, CPX, CPY, TX1, TY1)
      CALL CHKI('GQTXX AB', IERR, 0, NFAIL)
      CALL GQTXX(IWK, 0.1, 0.5, 'AB  ', IERR, CPX, CPY, TX2, TY2)
      CALL CHKI('GQTXX AB__', IERR, 0, NFAIL)
      IF (TX2(2) .LE. TX1(2) + 0.02) THEN
        WRITE (*, *) 'FAIL trailing blanks lost', TX1(2), TX2(2)
        NFAIL = NFAIL + 1
      END IF
C     Item 4: an escape that returns no data leaves LODR alone.
      LODR = -77
      WRITE (IDR(1), '(I10)') IWK
      IDR(2) = 'f77_compat_esc'
      CALL GESC(-101, 2, IDR, 1, LODR, ODR)
      CALL CHKI('GESC LODR untouched', LODR, -77, NFAIL)
C     Item 5: lines on the right and top edges of NDC are drawn.
      XS(1) = 1.0
      XS(2) = 1.0
      YS(1) = 0.0
      YS(2) = 1.0
      CALL GPL(2, XS, YS)
      XS(1) = 0.0
      YS(1) = 1.0
      CALL GPL(2, XS, YS)
      CALL GQPX(IWK, 1.0 - 0.5/1024.0, 0.5, IERR, I1)
      CALL CHKI('GQPX errind', IERR, 0, NFAIL)
      CALL CHKI('right edge drawn', I1, 1, NFAIL)
      CALL GQPX(IWK, 0.5, 1.0 - 0.5/1024.0, IERR, I1)
      CALL CHKI('top edge drawn', I1, 1, NFAIL)
      CALL GQPX(IWK, 0.5, 0.5, IERR, I1)
      CALL CHKI('inside background', I1, 0, NFAIL)
C     Item 9: GEVVWM reports in ERR only, not through GERHND.
      CALL GEVVWM(0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, GNDC,
     +            IERR, VWM)
      CALL CHKI('GEVVWM parallel', IERR, 561, NFAIL)
      CALL CHKI('GEVVWM no GERHND call', NERR, 0, NFAIL)
C     Added inquiries: colour facilities, predefined colour, indices.
      CALL GQCF(100, IERR, I1, I2, I3)
      CALL CHKI('GQCF errind', IERR, 0, NFAIL)
      CALL CHKI('GQCF NCOLI', I1, 256, NFAIL)
      CALL CHKI('GQCF COLA', I2, GCOLOR, NFAIL)
      CALL CHKI('GQCF NPCI', I3, 8, NFAIL)
      CALL GQPCR(100, 4, IERR, R, G, B)
      CALL CHKI('GQPCR errind', IERR, 0, NFAIL)
      IF (R .NE. 0.0 .OR. G .NE. 0.0 .OR. B .NE. 1.0) THEN
        WRITE (*, *) 'FAIL GQPCR 4 not blue', R, G, B
        NFAIL = NFAIL + 1
      END IF
      CALL GQECI(IWK, 0, IERR, I1, I2)
      CALL CHKI('GQECI count', I1, 8, NFAIL)
      CALL GQECI(IWK, 3, IERR, I1, I2)
      CALL CHKI('GQECI 3rd', I2, 2, NFAIL)
      CALL GQECI(IWK, 9, IERR, I1, I2)
      CALL CHKI('GQECI 9th', IERR, 2002, NFAIL)
      CALL GQDDS(100, IERR, I1, I2)
      CALL CHKI('GQDDS', I1 * 10 + I2, GASAP * 10 + GSUPPD, NFAIL)
      CALL GDAWK(IWK)
      CALL GCLWK(IWK)
C     NCAR's escapes as NCAR's fgke03 calls them: -1391 names the file
C     of the next workstation opened (its CONID 2 would be gks2.png),
C     twice in turn; -1396 (pause) updates the workstation named.
      OPEN (UNIT=31, FILE='gks2.png')
      CLOSE (31, STATUS='DELETE')
      IDR(1) = 'f77_meta01'
      CALL GESC(-1391, 1, IDR, 1, 1, ODR)
      CALL GOPWK(IWK, 2, 100)
      CALL GACWK(IWK)
      CALL GPL(2, XS, YS)
      WRITE (IDR(1), '(I5)') IWK
      CALL GESC(-1396, 1, IDR, 1, 1, ODR)
      CALL CHKI('GESC -1391, -1396', NERR, 0, NFAIL)
      IDR(1) = '   77'
      CALL GESC(-1396, 1, IDR, 1, 1, ODR)
      CALL CHKI('GESC -1396 no such ws', LASTE, 182, NFAIL)
      CALL GDAWK(IWK)
      CALL GCLWK(IWK)
      IDR(1) = 'f77_meta02'
      CALL GESC(-1391, 1, IDR, 1, 1, ODR)
      CALL GOPWK(IWK, 2, 100)
      CALL GCLWK(IWK)
      INQUIRE (FILE='f77_meta01.png', EXIST=EX1)
      INQUIRE (FILE='f77_meta02.png', EXIST=EX2)
      INQUIRE (FILE='gks2.png', EXIST=EX3)
      IF (.NOT. EX1 .OR. .NOT. EX2 .OR. EX3) THEN
        WRITE (*, *) 'FAIL GESC -1391 files', EX1, EX2, EX3
        NFAIL = NFAIL + 1
      END IF
      CALL GCLKS
      IF (NFAIL .EQ. 0) WRITE (*, '(A)') 'ALL OK'
      END

      SUBROUTINE CHKI(WHAT, GOT, WANT, NFAIL)
      CHARACTER*(*) WHAT
      INTEGER GOT, WANT, NFAIL
      IF (GOT .NE. WANT) THEN
        WRITE (*, '(A, A, A, I8, A, I8)') 'FAIL ', WHAT, ': ', GOT,
     +    ' want', WANT
        NFAIL = NFAIL + 1
      END IF
      END

C     The application's ERROR HANDLING replaces the library's: it counts.
      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
      INTEGER ERRNR, FCTID, ERRFIL
      INTEGER NERR, LASTE
      COMMON /ERRS/ NERR, LASTE
      NERR = NERR + 1
      LASTE = ERRNR
      CALL GERLOG(ERRNR, FCTID, ERRFIL)
      END
