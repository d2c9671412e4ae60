# SPDX-License-Identifier: MIT
# The direction of the modules (docs/ARCHITECTURE.md): which folders below src/c a module
# may not see. gks_module (CMakeLists.txt here) stops the configuration on a violation;
# tests/core/check_direction.cmake runs the same rules on allowed and refused examples.
#
#   - a driver (ws/<driver>) never sees the core's state: core, core/api, core/store; what
#     it needs comes through ws_driver.h. Of core/pipe a driver drawing text itself may use
#     the text layout (gks_text_layout.h, no GKS state); the pipeline's other headers
#     include the core's and do not compile there;
#   - a driver never sees another driver: of the folders below ws it sees ws/render, the
#     render layer every drawing workstation shares, and ws/mf, the metafile format; the
#     render layer sees no driver (the drivers are its output sinks);
#   - the core (core, core/api, core/pipe, core/store) never sees a renderer or a driver:
#     raster, ws/<driver>; it reaches the drivers through the driver table (ws) and TEXT's
#     glyphs in font; ws/mf, the metafile format, is shared;
#   - the leaves (base, xform, font, raster) see base alone.
#
# gks_direction_error(<out> <folder> <seen folders...>): <out> is the message for the
# first refused folder, or empty.
function(gks_direction_error out rel)
  set(msg "")
  foreach(d IN LISTS ARGN)
    set(why "")
    if(rel MATCHES "^ws(/|$)" AND d MATCHES "^core(/api|/store)?$")
      set(why "a driver sees ws/, base/ and the renderers")
    elseif(rel MATCHES "^ws/" AND d MATCHES "^ws/" AND NOT d STREQUAL rel AND
           NOT d MATCHES "^ws/(render|mf)$")
      set(why "a driver sees the render layer ws/render and ws/mf, never another driver")
    elseif(rel MATCHES "^core(/|$)" AND (d STREQUAL "raster" OR
                                         (d MATCHES "^ws/" AND NOT d STREQUAL "ws/mf")))
      set(why "the core reaches the drivers through ws/ and the glyphs in font/")
    elseif(rel MATCHES "^(base|xform|font|raster)$" AND NOT d STREQUAL "base")
      set(why "a leaf module sees base/ alone")
    endif()
    if(why)
      set(msg "src/c/${rel} may not see src/c/${d}: ${why} (docs/ARCHITECTURE.md)")
      break()
    endif()
  endforeach()
  set(${out} "${msg}" PARENT_SCOPE)
endfunction()
