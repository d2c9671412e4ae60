# SPDX-License-Identifier: MIT
# The direction rules of src/c/gks_direction.cmake (what gks_module refuses at configure
# time) on examples: the present layout passes, and each dependency that the rules exist
# to stop is refused, among them the old one of the text layout on the raster module.
#   cmake -DSRC=<source dir> -P check_direction.cmake
include(${SRC}/src/c/gks_direction.cmake)
set(failed 0)
function(expect want rel)
  gks_direction_error(err "${rel}" ${ARGN})
  if(want STREQUAL "ok" AND err)
    message(SEND_ERROR "refused: ${rel} sees ${ARGN}: ${err}")
  elseif(want STREQUAL "refused" AND NOT err)
    message(SEND_ERROR "not refused: ${rel} sees ${ARGN}")
  else()
    message(STATUS "${want}: ${rel} sees ${ARGN} ${err}")
  endif()
endfunction()
# as the tree has them
expect(ok core/pipe core core/pipe core/store ws ws/mf base xform font)
expect(ok core core core/api core/pipe core/store ws ws/mf base xform font)
expect(ok core/store core ws ws/mf base xform)
expect(ok ws/cairo ws ws/render base raster xform font core/pipe)
expect(ok ws/png ws ws/render base raster xform)
expect(ok ws/x11 ws ws/render base raster xform)
expect(ok ws/render ws base raster xform)
expect(ok ws/mo ws ws/mf base)
expect(ok font base)
expect(ok raster base)
expect(ok xform base)
# refused
expect(refused core/pipe core base raster) # the text layout's font from the rasterizer
expect(refused core core base raster)
expect(refused core/api core ws/png)
expect(refused core/store core ws/cairo)
expect(refused ws/png ws core)
expect(refused ws/cairo ws core/api)
expect(refused ws/x11 ws core/store)
expect(refused ws/cairo ws ws/png base raster) # sideways into another driver
expect(refused ws/x11 ws ws/png base raster)
expect(refused ws/render ws ws/png base raster) # the render layer knows no sink
expect(refused core ws/render)
expect(refused font base raster)
expect(refused raster base font)
expect(refused xform base core)
