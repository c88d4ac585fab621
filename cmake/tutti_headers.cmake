# SPDX-License-Identifier: MIT
# Every library is included as <tutti/<folder>/header.hpp>, in the build tree as when installed.
# In the build tree the include root (build/include) holds a link tutti/<folder> to each library
# folder, so the source tree keeps its layers (engine/, systems/, app/, ...) while the include
# names stay the library names. `cmake --install` copies the headers to include/tutti/<folder>.
set(TUTTI_INCLUDE_ROOT ${CMAKE_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${TUTTI_INCLUDE_ROOT}/tutti)

# tutti_headers(TARGET [INTERFACE]): TARGET's headers are those of its folder.
function(tutti_headers target)
  cmake_parse_arguments(ARG "INTERFACE" "" "" ${ARGN})
  get_filename_component(folder ${CMAKE_CURRENT_SOURCE_DIR} NAME)
  set(link ${TUTTI_INCLUDE_ROOT}/tutti/${folder})
  set(points_to "")
  if(IS_SYMLINK ${link})
    file(READ_SYMLINK ${link} points_to)
  endif()
  if(NOT points_to STREQUAL CMAKE_CURRENT_SOURCE_DIR)
    file(REMOVE ${link})
    file(CREATE_LINK ${CMAKE_CURRENT_SOURCE_DIR} ${link} SYMBOLIC)
  endif()
  set(scope PUBLIC)
  if(ARG_INTERFACE)
    set(scope INTERFACE)
  endif()
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${TUTTI_INCLUDE_ROOT}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
endfunction()
