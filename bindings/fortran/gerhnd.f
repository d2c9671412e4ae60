C     SPDX-License-Identifier: MIT
      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
!     ERROR HANDLING (ISO 8651-1): the library's default only logs the error.
!     An application replaces it by linking its own SUBROUTINE GERHND.
      INTEGER ERRNR, FCTID, ERRFIL
      CALL GERLOG(ERRNR, FCTID, ERRFIL)
      END
