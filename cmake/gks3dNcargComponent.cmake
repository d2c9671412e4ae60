# SPDX-License-Identifier: MIT
# find_package(gks3d COMPONENTS ncarg): the NCAR Graphics profile (docs/NCAR.md).
# Target gks3d::ncarg (libgks3d_ncarg.so, with gks3d::fortran), and gks3d::ncarg_static
# with COMPONENTS static. Link it where NCAR's link line has -lncarg_gks:
#   target_link_libraries(prog <libncarg.a> gks3d::ncarg <libncarg_c.a>)
set(gks3d_ncarg_FOUND FALSE)
if(TARGET gks3d::ncarg)
  set(gks3d_ncarg_FOUND TRUE)
endif()
