C     SPDX-License-Identifier: MIT
      SUBROUTINE CHKI(WHAT, GOT, WANT, NFAIL)
!     Test helper: counts and reports an integer mismatch.
      CHARACTER*(*) WHAT
      INTEGER GOT, WANT, NFAIL
      IF (GOT .NE. WANT) THEN
         WRITE (*, '(A, A, I0, A, I0)') WHAT, ': got ', GOT,
     +      ' want ', WANT
         NFAIL = NFAIL + 1
      END IF
      END

      SUBROUTINE CHKR(WHAT, GOT, WANT, NFAIL)
!     Test helper: counts and reports a real mismatch (tolerance 1E-6,
!     values pass through double precision unchanged).
      CHARACTER*(*) WHAT
      REAL GOT, WANT
      INTEGER NFAIL
      IF (ABS(GOT - WANT) .GT. 1.0E-6) THEN
         WRITE (*, '(A, A, G14.7, A, G14.7)') WHAT, ': got ', GOT,
     +      ' want ', WANT
         NFAIL = NFAIL + 1
      END IF
      END
