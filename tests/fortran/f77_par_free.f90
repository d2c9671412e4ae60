! SPDX-License-Identifier: MIT
! The INCLUDE files compile in free form too.
program parfree
  implicit none
  include 'GKS_PAR'
  include 'GKSE_PAR'
  write (*, '(A, I0, A, I0, A, I0)') 'GWSPNG=', GWSPNG, ' EOPKS=', EOPKS, ' GESSFN=', GESSFN
end program parfree
