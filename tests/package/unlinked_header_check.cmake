# SPDX-License-Identifier: MIT
# A library's headers are visible only to the targets that link it (cmake/tutti_headers.cmake).
# With the include directories a target hands on (INCLUDES, its transitive usage requirements),
# a unit including LINKED (a header of a library it links) compiles, and one including UNLINKED
# (a header of a library it does not link) fails for want of the file.
#   cmake -DCXX=compiler -DINCLUDES=dir;dir... -DLINKED=tutti/x/y.hpp -DUNLINKED=tutti/z/w.hpp
#         -P unlinked_header_check.cmake
set(flags "")
foreach(dir IN LISTS INCLUDES)
  if(dir)
    list(APPEND flags "-I${dir}")
  endif()
endforeach()
set(unit ${CMAKE_CURRENT_BINARY_DIR}/unlinked_header_check.cpp)
foreach(header IN ITEMS ${LINKED} ${UNLINKED})
  file(WRITE ${unit} "#include <${header}>\n")
  execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only ${flags} ${unit}
                  OUTPUT_VARIABLE out ERROR_VARIABLE errors RESULT_VARIABLE rc)
  if(header STREQUAL LINKED AND NOT rc EQUAL 0)
    message(FATAL_ERROR "<${header}>, of a linked library, does not compile: ${errors}")
  endif()
  if(header STREQUAL UNLINKED)
    if(rc EQUAL 0)
      message(FATAL_ERROR "<${header}> compiles without its library linked: its headers are visible to every target")
    endif()
    if(NOT errors MATCHES "No such file")
      message(FATAL_ERROR "<${header}> fails, but not for want of the file: ${errors}")
    endif()
  endif()
endforeach()
file(REMOVE ${unit})
message(STATUS "<${LINKED}> compiles where its library is linked; <${UNLINKED}> is not found where its library is not")
