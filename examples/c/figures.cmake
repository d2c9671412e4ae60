# SPDX-License-Identifier: MIT
# The paper's pictures (Fig. 2-5) through the C binding; included by examples/CMakeLists.txt.
# Fortran twins: examples/f77 (fig2_f77 ... fig5_f77, byte-identical PNG files).
foreach(n 2 3 4 5)
  add_executable(fig${n}_c ${CMAKE_CURRENT_LIST_DIR}/fig${n}.c ${CMAKE_CURRENT_LIST_DIR}/fig_scene.c)
  target_link_libraries(fig${n}_c PRIVATE gks3d_shared)
endforeach()
# A scientist's surface z = f(x, y) above a mirror (twin of examples/f77/surface.f).
add_executable(surface_c ${CMAKE_CURRENT_LIST_DIR}/surface.c)
target_link_libraries(surface_c PRIVATE gks3d_shared m)
