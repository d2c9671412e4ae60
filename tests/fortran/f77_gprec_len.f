C     SPDX-License-Identifier: MIT
      PROGRAM TPRECL
!     GPREC/GUREC sized by the program (issue 40 F, I): DATREC's
!     declared length (the hidden length) is used, never more. A short
!     CHARACTER*10 DATREC(4) in COMMON before a guard variable: a record
!     that fits is packed in elements of 10 and round-trips, one that
!     does not reports 2001; neither touches the guard. A long
!     CHARACTER*200 DATREC(2) with 65 strings (more than 64) round-trips
!     through GUREC. An array CHARACTER*20 DATREC(8) with integers,
!     reals and strings round-trips.
      INTEGER NFAIL, IERR, LDR, IL, RL, SL, I, IA(20), JA(20)
      INTEGER LS(65), JS(65)
      REAL RA(2), SA(2)
      CHARACTER*10 DS(4), GUARD
      CHARACTER*200 DL(2)
      CHARACTER*20 DA(8)
      CHARACTER*2 S65(65), T65(65)
      CHARACTER*8 S2(2), T2(2)
      COMMON /SHORT/ DS, GUARD
      NFAIL = 0
      GUARD = 'UNTOUCHED!'
!     Short: 'GKSR3,0,0,1,2,3,' is 16 characters, 2 elements of 10.
      IA(1) = 1
      IA(2) = 2
      IA(3) = 3
      CALL GPREC(3, IA, 0, RA, 0, LS, S2, 4, IERR, LDR, DS)
      CALL CHKI('GPREC short', IERR, 0, NFAIL)
      CALL CHKI('GPREC short LDR', LDR, 2, NFAIL)
      IF (GUARD .NE. 'UNTOUCHED!') THEN
         WRITE (*, '(2A)') 'short: guard: got ', GUARD
         NFAIL = NFAIL + 1
      END IF
      CALL GUREC(LDR, DS, 20, 2, 2, IERR, IL, JA, RL, SA, SL, JS, T2)
      CALL CHKI('GUREC short', IERR, 0, NFAIL)
      CALL CHKI('GUREC short IL', IL, 3, NFAIL)
      CALL CHKI('GUREC short IA(3)', JA(3), 3, NFAIL)
!     Short and too small: 20 integers do not fit into 40 characters.
      DO 10 I = 1, 20
         IA(I) = 1000 + I
   10 CONTINUE
      CALL GPREC(20, IA, 0, RA, 0, LS, S2, 4, IERR, LDR, DS)
      CALL CHKI('GPREC short full', IERR, 2001, NFAIL)
      IF (GUARD .NE. 'UNTOUCHED!') THEN
         WRITE (*, '(2A)') 'short full: guard: got ', GUARD
         NFAIL = NFAIL + 1
      END IF
!     Long: 65 strings of 2 characters, 271 characters in 2 of 200.
      DO 20 I = 1, 65
         WRITE (S65(I), '(I2.2)') I
         LS(I) = 2
   20 CONTINUE
      CALL GPREC(0, IA, 0, RA, 65, LS, S65, 2, IERR, LDR, DL)
      CALL CHKI('GPREC long', IERR, 0, NFAIL)
      CALL CHKI('GPREC long LDR', LDR, 2, NFAIL)
      CALL GUREC(LDR, DL, 1, 1, 65, IERR, IL, JA, RL, SA, SL, JS, T65)
      CALL CHKI('GUREC long', IERR, 0, NFAIL)
      CALL CHKI('GUREC long SL', SL, 65, NFAIL)
      CALL CHKI('GUREC long LSTR(65)', JS(65), 2, NFAIL)
      IF (T65(1) .NE. '01' .OR. T65(65) .NE. '65') THEN
         WRITE (*, '(4A)') 'long strings: got ', T65(1), ' ', T65(65)
         NFAIL = NFAIL + 1
      END IF
!     Array: integers, reals and strings in elements of 20.
      RA(1) = 0.25
      RA(2) = -7.5
      S2(1) = 'ALPHA'
      S2(2) = 'BETA'
      LS(1) = 5
      LS(2) = 4
      CALL GPREC(3, IA, 2, RA, 2, LS, S2, 8, IERR, LDR, DA)
      CALL CHKI('GPREC array', IERR, 0, NFAIL)
      CALL GUREC(LDR, DA, 20, 2, 2, IERR, IL, JA, RL, SA, SL, JS, T2)
      CALL CHKI('GUREC array', IERR, 0, NFAIL)
      CALL CHKI('GUREC array IA(3)', JA(3), 1003, NFAIL)
      CALL CHKR('GUREC array RA(2)', SA(2), -7.5, NFAIL)
      CALL CHKI('GUREC array SL', SL, 2, NFAIL)
      IF (T2(1) .NE. 'ALPHA' .OR. T2(2) .NE. 'BETA') THEN
         WRITE (*, '(4A)') 'array strings: got ', T2(1), ' ', T2(2)
         NFAIL = NFAIL + 1
      END IF
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 GPREC LEN PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 GPREC LEN FAIL ', NFAIL
         STOP 1
      END IF
      END
