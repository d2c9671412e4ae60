# SPDX-License-Identifier: MIT
# gks3d_origin_runpath(<target> <install dir> <runpath>) -- a library or program of ours
# that needs a library of ours finds it relative to itself: libgks3d_fortran.so (installed
# into <libdir>) needs libgks3d.so.0 beside it, RUNPATH $ORIGIN, so that a program linked
# against it from any prefix runs with no environment variable (the program's own RUNPATH
# does not apply to the dependencies of its libraries); the programs in <bindir> get
# $ORIGIN/../<libdir>. Installed into the system prefix (/usr, /usr/local) the library gets no
# RUNPATH at all (Debian policy: the loader's default path finds it). The prefix is the
# one of the install step (cmake --install --prefix P decides, not the configure step), so
# the RUNPATH is set at link time and removed by an install-time rule. A packager who sets
# CMAKE_SKIP_INSTALL_RPATH gets none anywhere.
# Call it after the install(TARGETS) of <target> (the rule runs after the file is there).
function(gks3d_origin_runpath target dir runpath)
  if(CMAKE_SKIP_INSTALL_RPATH OR CMAKE_SKIP_RPATH)
    return()
  endif()
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "${runpath}")
  install(CODE "
    set(_gks3d_prefix \"\${CMAKE_INSTALL_PREFIX}\")
    string(REGEX REPLACE \"/+$\" \"\" _gks3d_prefix \"\${_gks3d_prefix}\")
    if(_gks3d_prefix STREQUAL \"/usr\" OR _gks3d_prefix STREQUAL \"/usr/local\")
      set(_gks3d_lib \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${dir}/$<TARGET_FILE_NAME:${target}>\")
      message(STATUS \"System prefix: no RUNPATH in \${_gks3d_lib}\")
      file(RPATH_REMOVE FILE \"\${_gks3d_lib}\")
    endif()")
endfunction()
