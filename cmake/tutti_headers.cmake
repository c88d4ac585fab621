# SPDX-License-Identifier: MIT
# Every library is included as <tutti/<folder>/header.hpp>, in the build tree as when installed.
# In the build tree each library has an include root of its own, build/include-by-library/<folder>,
# holding one link tutti/<folder> to its folder: a target sees the headers of the libraries it
# links (directly or through their public links) and no others, so a missing link fails to
# compile instead of linking by luck. The source tree keeps its layers (engine/, systems/,
# app/, ...) while the include names stay the library names. build/include links every library
# folder under one root, for the checks that read headers outside any target (the host header's,
# the layering test). `cmake --install` copies the headers to include/tutti/<folder>.
set(TUTTI_INCLUDE_ROOT ${CMAKE_BINARY_DIR}/include)
set(TUTTI_LIBRARY_INCLUDE_ROOTS ${CMAKE_BINARY_DIR}/include-by-library)
file(MAKE_DIRECTORY ${TUTTI_INCLUDE_ROOT}/tutti)

# tutti_link_folder(LINK TARGET_DIR): LINK becomes a symbolic link to TARGET_DIR (kept if it is).
function(tutti_link_folder link target_dir)
  set(points_to "")
  if(IS_SYMLINK ${link})
    file(READ_SYMLINK ${link} points_to)
  endif()
  if(NOT points_to STREQUAL target_dir)
    get_filename_component(parent ${link} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    file(REMOVE ${link})
    file(CREATE_LINK ${target_dir} ${link} SYMBOLIC)
  endif()
endfunction()

# tutti_headers(TARGET [INTERFACE]): TARGET's headers are those of its folder.
function(tutti_headers target)
  cmake_parse_arguments(ARG "INTERFACE" "" "" ${ARGN})
  get_filename_component(folder ${CMAKE_CURRENT_SOURCE_DIR} NAME)
  tutti_link_folder(${TUTTI_INCLUDE_ROOT}/tutti/${folder} ${CMAKE_CURRENT_SOURCE_DIR})
  tutti_link_folder(${TUTTI_LIBRARY_INCLUDE_ROOTS}/${folder}/tutti/${folder} ${CMAKE_CURRENT_SOURCE_DIR})
  set(scope PUBLIC)
  if(ARG_INTERFACE)
    set(scope INTERFACE)
  endif()
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${TUTTI_LIBRARY_INCLUDE_ROOTS}/${folder}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
endfunction()

# tutti_add_folders(): add_subdirectory for every folder of the current source folder that has a
# CMakeLists.txt, in name order, so that a new family's folders (its systems, its tests) need no
# line in a list.
function(tutti_add_folders)
  file(GLOB folders LIST_DIRECTORIES true RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}
       CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*)
  list(SORT folders)
  foreach(folder IN LISTS folders)
    if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${folder}/CMakeLists.txt)
      add_subdirectory(${folder})
    endif()
  endforeach()
endfunction()
