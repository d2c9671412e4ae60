C     SPDX-License-Identifier: MIT
      PROGRAM MFILE
!     The GKS metafile through the Fortran binding: GWITM writes a user
!     item to an MO workstation (CONID 31: file gks31.gksm), a polyline
!     with linetype 3 follows; an MI workstation on the same file reads
!     the items back with GGTITM / GRDITM and performs them with GIITM
!     (the current linetype becomes 3 again). Errors 160, 161, 34, 167,
!     162 reach the program's own GERHND.
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INCLUDE 'GKSE_PAR'
      INTEGER N, ERRS(20), FCTS(20)
      COMMON /ERRREC/ N, ERRS, FCTS
      INTEGER NFAIL, ITYPE, ILEN, NITEM, IERR, LTYPE
      CHARACTER*80 REC(16)
      REAL PX(2), PY(2)
      DATA PX /0.1, 0.9/, PY /0.5, 0.5/
      N = 0
      NFAIL = 0
      CALL GOPKS(6, -1)
      CALL GOPWK(1, 0, GWSNUL)
      CALL GOPWK(2, 31, GWSMO)
      CALL GACWK(1)
      CALL GACWK(2)
      REC(1) = 'hello metafile'
      CALL GWITM(2, 123, 14, 1, REC)
      CALL GWITM(2, 50, 14, 1, REC)
      CALL GWITM(2, 123, 81, 1, REC)
      CALL CHKI('GWITM errors', N, 2, NFAIL)
      CALL CHKI('GWITM 160', ERRS(1), 160, NFAIL)
      CALL CHKI('GWITM fct', FCTS(1), EWITM, NFAIL)
      CALL CHKI('GWITM 161', ERRS(2), 161, NFAIL)
      CALL GSLN(3)
      CALL GPL(2, PX, PY)
      CALL GSLN(1)
      CALL GDAWK(2)
      CALL GCLWK(2)
      N = 0
      CALL GOPWK(3, 31, GWSMI)
      CALL GGTITM(1, ITYPE, ILEN)
      CALL CHKI('GGTITM on OUTPUT ws', ERRS(1), 34, NFAIL)
      CALL GGTITM(3, ITYPE, ILEN)
      CALL CHKI('GGTITM type', ITYPE, 123, NFAIL)
      CALL CHKI('GGTITM length', ILEN, 14, NFAIL)
      REC(1) = ' '
      CALL GRDITM(3, 80, 1, REC)
      IF (REC(1) .NE. 'hello metafile') THEN
         WRITE (*, '(A, A)') 'GRDITM record: got ', REC(1)
         NFAIL = NFAIL + 1
      END IF
      CALL GIITM(123, 14, 1, REC)
      CALL CHKI('GIITM user item', ERRS(2), 167, NFAIL)
      CALL CHKI('GIITM fct', FCTS(2), EIITM, NFAIL)
      NITEM = 0
   10 CONTINUE
      CALL GGTITM(3, ITYPE, ILEN)
      IF (ILEN .GT. 80*16) THEN
         WRITE (*, '(A, I0)') 'item too long for REC: ', ILEN
         NFAIL = NFAIL + 1
         GOTO 20
      END IF
      CALL GRDITM(3, ILEN, 16, REC)
      IF (ITYPE .NE. 0) THEN
         CALL GIITM(ITYPE, ILEN, 16, REC)
         NITEM = NITEM + 1
         GOTO 10
      END IF
   20 CONTINUE
      CALL CHKI('errors while interpreting', N, 2, NFAIL)
      IF (NITEM .LT. 10) THEN
         WRITE (*, '(A, I0)') 'too few items: ', NITEM
         NFAIL = NFAIL + 1
      END IF
      CALL GQLN(IERR, LTYPE)
      CALL CHKI('linetype after GIITM', LTYPE, 3, NFAIL)
      CALL GGTITM(3, ITYPE, ILEN)
      CALL CHKI('no item left', ERRS(3), 162, NFAIL)
      CALL GCLWK(3)
      CALL GDAWK(1)
      CALL GCLWK(1)
      CALL GCLKS
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, '(A)') 'F77 METAFILE PASS'
      ELSE
         WRITE (*, '(A, I0)') 'F77 METAFILE FAIL ', NFAIL
      END IF
      END

      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
!     The application's ERROR HANDLING: records, never logs.
      INTEGER ERRNR, FCTID, ERRFIL
      INTEGER N, ERRS(20), FCTS(20)
      COMMON /ERRREC/ N, ERRS, FCTS
      IF (N .GE. 20 .OR. ERRFIL .LT. 0) RETURN
      N = N + 1
      ERRS(N) = ERRNR
      FCTS(N) = FCTID
      END
