C     SPDX-License-Identifier: MIT
      PROGRAM LIGHT
!     The lighting extension of the Fortran binding: GSAPR, GSBAPR,
!     GSRFEQ, GSBRFQ, GSLSR, GSLSS round-tripped through GQAPR, GQBAPR,
!     GQRFEQ, GQLSR, GQLSS; the errors each reports (number and FCTID
!     through the program's own GERHND), state unchanged after an error;
!     the integer ray-tracing ESCAPE records of GESC, the vector
!     workstations' line style and page records.
      IMPLICIT NONE
      INCLUDE 'GKS_PAR'
      INCLUDE 'GKS3D_PAR'
      INCLUDE 'GKSE_PAR'
      INTEGER LASTE, LASTF, NERR
      COMMON /LASTER/ LASTE, LASTF, NERR
      INTEGER NFAIL, ERR, I, T, F, B, OL, L, LODR, NBEF
      REAL A, D, S, C(3), E, TR, R, P(3), V(3), AT(2), CX, SP
      REAL WC(3), WP(3), WV(3), WA(2)
      INTEGER ACT(2), DEA(1)
      CHARACTER*80 IDR(1), ODR(1)
      DATA WC /0.9, 0.8, 0.7/, WP /0.25, 0.5, 2.0/
      DATA WV /0.0, -1.0, 0.0/, WA /1.0, 0.5/
      NFAIL = 0
      NERR = 0
!     Inquiries before OPEN GKS: ERRIND 8, outputs untouched.
      A = -1.0
      CALL GQAPR(ERR, A, D, S, C, E, TR, R)
      CALL CHKI('GQAPR closed', ERR, 8, NFAIL)
      CALL CHKR('GQAPR closed A', A, -1.0, NFAIL)
      CALL GQRFEQ(ERR, F, B)
      CALL CHKI('GQRFEQ closed', ERR, 8, NFAIL)
      CALL GQLSS(0, ERR, OL, L)
      CALL CHKI('GQLSS closed', ERR, 8, NFAIL)
      CALL GOPKS(6, -1)
!     Defaults (gks.h): 1, 1, 0, white, 1, 0, 1; equations GRNONE.
      CALL GQAPR(ERR, A, D, S, C, E, TR, R)
      CALL CHKI('GQAPR', ERR, 0, NFAIL)
      CALL CHKR('default AMBC', A, 1.0, NFAIL)
      CALL CHKR('default DIFC', D, 1.0, NFAIL)
      CALL CHKR('default SPECC', S, 0.0, NFAIL)
      CALL CHKR('default SPCOL', C(3), 1.0, NFAIL)
      CALL CHKR('default SPEXP', E, 1.0, NFAIL)
      CALL CHKR('default TRANSC', TR, 0.0, NFAIL)
      CALL CHKR('default REFRI', R, 1.0, NFAIL)
      CALL GQRFEQ(ERR, F, B)
      CALL CHKI('default RFEQ', F, GRNONE, NFAIL)
      CALL CHKI('default BRFEQ', B, GRNONE, NFAIL)
!     Front and back properties are separate.
      CALL GSAPR(0.2, 0.7, 0.5, WC, 20.0, 0.25, 1.5)
      CALL GSBAPR(0.3, 0.6, 0.0, WC, 2.0, 0.0, 1.33)
      CALL CHKI('no error', NERR, 0, NFAIL)
      CALL GQAPR(ERR, A, D, S, C, E, TR, R)
      CALL CHKR('AMBC', A, 0.2, NFAIL)
      CALL CHKR('DIFC', D, 0.7, NFAIL)
      CALL CHKR('SPECC', S, 0.5, NFAIL)
      DO 10 I = 1, 3
         CALL CHKR('SPCOL', C(I), WC(I), NFAIL)
   10 CONTINUE
      CALL CHKR('SPEXP', E, 20.0, NFAIL)
      CALL CHKR('TRANSC', TR, 0.25, NFAIL)
      CALL CHKR('REFRI', R, 1.5, NFAIL)
      CALL GQBAPR(ERR, A, D, S, C, E, TR, R)
      CALL CHKI('GQBAPR', ERR, 0, NFAIL)
      CALL CHKR('back AMBC', A, 0.3, NFAIL)
      CALL CHKR('back SPEXP', E, 2.0, NFAIL)
      CALL CHKR('back REFRI', R, 1.33, NFAIL)
!     Bad values: 2000 (coefficient, refraction index), 96 (colour);
!     the properties stay as they were.
      CALL GSAPR(1.5, 0.7, 0.5, WC, 20.0, 0.25, 1.5)
      CALL CHKER('GSAPR AMBC 1.5', 2000, ESAPR, NFAIL)
      CALL GSAPR(0.5, 0.7, 0.5, WC, 20.0, 0.25, 0.0)
      CALL CHKER('GSAPR REFRI 0', 2000, ESAPR, NFAIL)
      C(1) = 0.5
      C(2) = 1.5
      C(3) = 0.5
      CALL GSBAPR(0.5, 0.7, 0.5, C, 20.0, 0.25, 1.5)
      CALL CHKER('GSBAPR colour', 96, ESBAPR, NFAIL)
      CALL GQAPR(ERR, A, D, S, C, E, TR, R)
      CALL CHKR('AMBC kept', A, 0.2, NFAIL)
      CALL CHKR('REFRI kept', R, 1.5, NFAIL)
      CALL GQBAPR(ERR, A, D, S, C, E, TR, R)
      CALL CHKR('back AMBC kept', A, 0.3, NFAIL)
!     Reflectance equations.
      CALL GSRFEQ(GRAMDS)
      CALL GSBRFQ(GRAMB)
      CALL GQRFEQ(ERR, F, B)
      CALL CHKI('RFEQ', F, GRAMDS, NFAIL)
      CALL CHKI('BRFEQ', B, GRAMB, NFAIL)
      CALL GSRFEQ(5)
      CALL CHKER('GSRFEQ 5', 524, ESRFEQ, NFAIL)
      CALL GSBRFQ(0)
      CALL CHKER('GSBRFQ 0', 524, ESBRFQ, NFAIL)
      CALL GQRFEQ(ERR, F, B)
      CALL CHKI('RFEQ kept', F, GRAMDS, NFAIL)
      CALL CHKI('BRFEQ kept', B, GRAMB, NFAIL)
!     Light source representation: a workstation function (error 7
!     while none is open), then round trip and errors 529, 531, 532.
      CALL GSLSR(1, 3, GPOSI, WC, WP, WV, WA, 0.0, 0.0)
      CALL CHKER('GSLSR GKOP', 7, ESLSR, NFAIL)
      CALL GOPWK(1, 1, GWSNUL)
      CALL GSLSR(1, 3, GPOSI, WC, WP, WV, WA, 2.0, 0.5)
      CALL CHKI('no error', NERR, 6, NFAIL)
      CALL GQLSR(1, 3, ERR, T, C, P, V, AT, CX, SP)
      CALL CHKI('GQLSR', ERR, 0, NFAIL)
      CALL CHKI('LSTYPE', T, GPOSI, NFAIL)
      DO 20 I = 1, 3
         CALL CHKR('COLR', C(I), WC(I), NFAIL)
         CALL CHKR('POS', P(I), WP(I), NFAIL)
         CALL CHKR('DIR', V(I), WV(I), NFAIL)
   20 CONTINUE
      CALL CHKR('ATTEN(1)', AT(1), 1.0, NFAIL)
      CALL CHKR('ATTEN(2)', AT(2), 0.5, NFAIL)
      CALL CHKR('CONCEX', CX, 2.0, NFAIL)
      CALL CHKR('SPREAD', SP, 0.5, NFAIL)
      CALL GSLSR(1, GMXLSI + 1, GPOSI, WC, WP, WV, WA, 0.0, 0.0)
      CALL CHKER('GSLSR index 65', 529, ESLSR, NFAIL)
      CALL GSLSR(1, 4, 5, WC, WP, WV, WA, 0.0, 0.0)
      CALL CHKER('GSLSR type 5', 531, ESLSR, NFAIL)
      CALL GSLSR(1, 4, GSPOT, WC, WP, WV, WA, 1.0, 4.0)
      CALL CHKER('GSLSR spread 4', 532, ESLSR, NFAIL)
      CALL GQLSR(1, 4, ERR, T, C, P, V, AT, CX, SP)
      CALL CHKI('GQLSR undefined', ERR, 2002, NFAIL)
      CALL GQLSR(1, 0, ERR, T, C, P, V, AT, CX, SP)
      CALL CHKI('GQLSR index 0', ERR, 529, NFAIL)
      CALL GQLSR(2, 3, ERR, T, C, P, V, AT, CX, SP)
      CALL CHKI('GQLSR ws 2', ERR, 25, NFAIL)
!     Index 1 is predefined: a white ambient light.
      CALL GQLSR(1, 1, ERR, T, C, P, V, AT, CX, SP)
      CALL CHKI('GQLSR 1', ERR, 0, NFAIL)
      CALL CHKI('LSTYPE 1', T, GAMB, NFAIL)
      CALL CHKR('COLR 1', C(2), 1.0, NFAIL)
!     Light source state: ascending list inquiry.
      ACT(1) = 3
      ACT(2) = 1
      CALL GSLSS(2, ACT, 0, DEA)
      CALL GQLSS(0, ERR, OL, L)
      CALL CHKI('GQLSS count', OL, 2, NFAIL)
      CALL GQLSS(1, ERR, OL, L)
      CALL CHKI('GQLSS 1', L, 1, NFAIL)
      CALL GQLSS(2, ERR, OL, L)
      CALL CHKI('GQLSS 2', L, 3, NFAIL)
      CALL GQLSS(3, ERR, OL, L)
      CALL CHKI('GQLSS 3', ERR, 2002, NFAIL)
      DEA(1) = 3
      CALL GSLSS(0, ACT, 1, DEA)
      CALL GQLSS(1, ERR, OL, L)
      CALL CHKI('GQLSS after off', OL, 1, NFAIL)
      CALL CHKI('GQLSS after off 1', L, 1, NFAIL)
      ACT(1) = 2
      DEA(1) = 2
      CALL GSLSS(1, ACT, 1, DEA)
      CALL CHKER('GSLSS both', 535, ESLSS, NFAIL)
      ACT(1) = 0
      CALL GSLSS(1, ACT, 0, DEA)
      CALL CHKER('GSLSS 0', 533, ESLSS, NFAIL)
      CALL GQLSS(0, ERR, OL, L)
      CALL CHKI('GQLSS kept', OL, 1, NFAIL)
!     GESC integer records: clip secondary rays on a PNG workstation.
      CALL GOPWK(2, 77, GWSPNG)
      WRITE (IDR(1), '(2I10)') 2, 1
      CALL GESC(GESRCS, 1, IDR, 1, LODR, ODR)
      CALL CHKI('GESC -102', NERR, 11, NFAIL)
      WRITE (IDR(1), '(2I10)') 2, 7
      CALL GESC(GESRCS, 1, IDR, 1, LODR, ODR)
      CALL CHKER('GESC -102 value 7', 182, EESC, NFAIL)
      IDR(1) = '         2       abc'
      CALL GESC(GESRCS, 1, IDR, 1, LODR, ODR)
      CALL CHKER('GESC -102 malformed', 182, EESC, NFAIL)
      CALL GESC(GESRMD, 0, IDR, 1, LODR, ODR)
      CALL CHKER('GESC -104 LIDR 0', 182, EESC, NFAIL)
!     PNG workstation escapes: compression 9 accepted, 10 is 182;
!     anti-aliasing 4 accepted, 0 is 182.
      WRITE (IDR(1), '(2I10)') 2, 9
      CALL GESC(GESPZC, 1, IDR, 1, LODR, ODR)
      CALL CHKI('GESC -111', NERR, 14, NFAIL)
      WRITE (IDR(1), '(2I10)') 2, 10
      CALL GESC(GESPZC, 1, IDR, 1, LODR, ODR)
      CALL CHKER('GESC -111 value 10', 182, EESC, NFAIL)
      WRITE (IDR(1), '(2I10)') 2, 4
      CALL GESC(GESPAA, 1, IDR, 1, LODR, ODR)
      CALL CHKI('GESC -110', NERR, 15, NFAIL)
      WRITE (IDR(1), '(2I10)') 2, 0
      CALL GESC(GESPAA, 1, IDR, 1, LODR, ODR)
      CALL CHKER('GESC -110 value 0', 182, EESC, NFAIL)
!     vector line style and page (a PDF workstation, if the build has
!     cairo; else OPEN WORKSTATION answers 23 and this part is left):
!     a real record (E20 in columns 11-30), an integer one, a page of
!     six values; errors of this part are not counted below.
      NBEF = NERR
      CALL GOPWK(3, 78, GWSPDF)
      IF (NERR .EQ. NBEF) THEN
        WRITE (IDR(1), '(I10,E20.7)') 3, 2.5
        CALL GESC(GESVML, 1, IDR, 1, LODR, ODR)
        CALL CHKI('GESC -115', NERR, NBEF, NFAIL)
        WRITE (IDR(1), '(I10,F20.3)') 3, 0.5
        CALL GESC(GESVML, 1, IDR, 1, LODR, ODR)
        CALL CHKER('GESC -115 value 0.5', 182, EESC, NFAIL)
        IDR(1) = '         3         x'
        CALL GESC(GESVLS, 1, IDR, 1, LODR, ODR)
        CALL CHKER('GESC -116 malformed', 182, EESC, NFAIL)
        WRITE (IDR(1), '(2I10)') 3, 2
        CALL GESC(GESVLJ, 1, IDR, 1, LODR, ODR)
        WRITE (IDR(1), '(7I10)') 3, 72, 72, 216, 216, 612, 792
        CALL GESC(GESVPG, 1, IDR, 1, LODR, ODR)
        CALL CHKI('GESC -113, -117', NERR, NBEF + 2, NFAIL)
        CALL GCLWK(3)
      ENDIF
      NERR = NBEF
      CALL GCLWK(2)
      CALL GCLWK(1)
      CALL GCLKS
      CALL CHKI('error count', NERR, 16, NFAIL)
      IF (NFAIL .EQ. 0) WRITE (*, '(A)') 'F77 LIGHT PASS'
      END

      SUBROUTINE GERHND(ERRNR, FCTID, ERRFIL)
!     The program's own ERROR HANDLING: remembers the last error.
      INTEGER ERRNR, FCTID, ERRFIL
      INTEGER LASTE, LASTF, NERR
      COMMON /LASTER/ LASTE, LASTF, NERR
      LASTE = ERRNR
      LASTF = FCTID
      NERR = NERR + 1
      IF (ERRFIL .LT. 0) NERR = -1000
      END

      SUBROUTINE CHKER(WHAT, WERR, WFCT, NFAIL)
!     Checks that the last call reported error WERR in function WFCT.
      CHARACTER*(*) WHAT
      INTEGER WERR, WFCT, NFAIL
      INTEGER LASTE, LASTF, NERR
      COMMON /LASTER/ LASTE, LASTF, NERR
      CALL CHKI(WHAT, LASTE, WERR, NFAIL)
      CALL CHKI(WHAT, LASTF, WFCT, NFAIL)
      LASTE = 0
      LASTF = -1
      END
