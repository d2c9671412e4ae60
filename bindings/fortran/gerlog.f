C     SPDX-License-Identifier: MIT
      SUBROUTINE GERLOG(ERRNR, FCTID, ERRFIL)
!     ERROR LOGGING (ISO 8651-1): writes the error number, the function
!     name and the standard message (with what went wrong, GKEMSG:
!     the file and the reason) as one line to unit ERRFIL.
      INTEGER ERRNR, FCTID, ERRFIL
      CHARACTER*64 FNAM
      CHARACTER*800 MSG
      INTEGER LF, LM
      CALL GKFNAM(FCTID, FNAM, LF)
      CALL GKEMSG(ERRNR, MSG, LM)
      LF = MAX(LF, 1)
      LM = MAX(LM, 1)
      WRITE (ERRFIL, 100) ERRNR, FNAM(1:LF), MSG(1:LM)
      FLUSH (ERRFIL)
  100 FORMAT ('GKS ERROR ', I0, ' in ', A, ': ', A)
      END
