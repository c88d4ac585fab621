# SPDX-License-Identifier: MIT
# `cmake --install`: tutti as a relocatable CMake package (docs/embedding.md, "Using the installed
# package"). Installed: the libraries below and their headers (include/tutti/<folder>/*.hpp, the
# same paths the code includes), lib/cmake/tutti/ (tuttiConfig.cmake, tuttiConfigVersion.cmake,
# tuttiTargets.cmake), and the data: content/ and the generated .glb assets under share/tutti/
# (the rules are in content/CMakeLists.txt and content/generator/CMakeLists.txt).
# Components: "dev" (headers, libraries, CMake files) and "data" (content, assets).
include(CMakePackageConfigHelpers)

# The libraries a game links, exported as tutti::<name> (tutti_core -> tutti::core). Their
# include directories are $<BUILD_INTERFACE:...> / $<INSTALL_INTERFACE:include> and
# tutti_warnings is $<BUILD_INTERFACE:...> in their link lines, so neither the source tree nor
# the warning flags reach a consumer. Three export sets, so a machine needs only the packages of
# what it uses:
#  - tuttiTargets: staging and sampling performances (tutti::performance, the C API tutti::c,
#    tutti::export, the systems): no Vulkan, no window, no sound device;
#  - tuttiSoundTargets: FluidSynth sound and live MIDI input (tutti::audio, tutti::live);
#  - tuttiRenderTargets: the Vulkan renderer, windows, the runtime and tutti::tutti.
#
# The systems' and the families' libraries are found in their folders (systems/, plugins/), so a
# new family's libraries are exported with nothing to add here.
function(_tutti_libraries_under dir out)
  set(found)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(target MATCHES "^tutti_" AND type MATCHES "_LIBRARY$")
      list(APPEND found ${target})
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    _tutti_libraries_under(${subdir} below)
    list(APPEND found ${below})
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()
_tutti_libraries_under(${PROJECT_SOURCE_DIR}/systems _tutti_system_libraries)
_tutti_libraries_under(${PROJECT_SOURCE_DIR}/plugins _tutti_family_libraries)
set(TUTTI_PERFORMANCE_TARGETS
  tutti_core tutti_ecs tutti_components tutti_music tutti_content tutti_image tutti_model
  tutti_humanoid
  tutti_scene tutti_stage tutti_performance tutti_c
  tutti_export
  ${_tutti_system_libraries} ${_tutti_family_libraries})
set(TUTTI_SOUND_TARGETS tutti_audio tutti_live)
set(TUTTI_RENDER_TARGETS
  tutti_render tutti_render_window tutti_shader_compiler tutti_runtime tutti_runtime_imgui)
set(TUTTI_EXPORTED_TARGETS
  ${TUTTI_PERFORMANCE_TARGETS} ${TUTTI_SOUND_TARGETS} ${TUTTI_RENDER_TARGETS})
# Libraries of the programs and the tests, not installed.
set(TUTTI_INTERNAL_TARGETS
  tutti_warnings tutti_app tutti_app_play tutti_app_stream_report tutti_content_generator_lib
  tutti_editor_core tutti_editor_ui)

# tutti::tutti: everything a game needs (staging, the runtime, the renderer and its window, the
# sound, live input, every system). Not in it: tutti::runtime_imgui (Dear ImGui) and
# tutti::shader_compiler (glslang, for shader hot reload); link those by name.
add_library(tutti_all INTERFACE)
add_library(tutti::tutti ALIAS tutti_all)
set_target_properties(tutti_all PROPERTIES EXPORT_NAME tutti)
set(_tutti_umbrella ${TUTTI_EXPORTED_TARGETS})
list(REMOVE_ITEM _tutti_umbrella tutti_runtime_imgui tutti_shader_compiler tutti_c)
target_link_libraries(tutti_all INTERFACE ${_tutti_umbrella})

foreach(target IN LISTS TUTTI_EXPORTED_TARGETS)
  string(REGEX REPLACE "^tutti_" "" name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  # The headers are C++20 (the same -std as the build: CMAKE_CXX_STANDARD is 20).
  get_target_property(type ${target} TYPE)
  if(target STREQUAL "tutti_c")
    # A C interface: a C program links it without C++20 (or C++) being asked of it.
  elseif(type STREQUAL "INTERFACE_LIBRARY")
    target_compile_features(${target} INTERFACE cxx_std_20)
  else()
    target_compile_features(${target} PUBLIC cxx_std_20)
  endif()
endforeach()

# A new library must be put in one of the two lists: exported (then its CMakeLists needs the
# generator expressions above) or internal.
function(_tutti_check_library_lists dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(target MATCHES "^tutti_" AND type MATCHES "_LIBRARY$" AND NOT target STREQUAL "tutti_all"
       AND NOT target IN_LIST TUTTI_EXPORTED_TARGETS AND NOT target IN_LIST TUTTI_INTERNAL_TARGETS)
      message(WARNING "${target} (${dir}) is in neither TUTTI_EXPORTED_TARGETS nor "
                      "TUTTI_INTERNAL_TARGETS (cmake/tutti_package.cmake)")
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    _tutti_check_library_lists(${subdir})
  endforeach()
endfunction()
_tutti_check_library_lists(${PROJECT_SOURCE_DIR})

# The public headers: every .hpp in the folders of the exported libraries, at its path relative
# to the include root (engine/, systems/ or the top folder for components/). The same list feeds
# tests/package (each header compiled on its own).
set(TUTTI_PUBLIC_HEADERS)       # as included: "model/model_asset.hpp"
set(TUTTI_PUBLIC_HEADER_FILES)  # the files in the source tree
set(_tutti_header_trees)
foreach(target IN LISTS TUTTI_EXPORTED_TARGETS)
  get_target_property(dir ${target} SOURCE_DIR)
  list(APPEND _tutti_header_trees ${dir})
endforeach()
list(REMOVE_DUPLICATES _tutti_header_trees)
foreach(tree IN LISTS _tutti_header_trees)
  get_filename_component(root ${tree} DIRECTORY)
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS RELATIVE ${root} ${tree}/*.hpp)
  list(SORT headers)
  foreach(header IN LISTS headers)
    list(APPEND TUTTI_PUBLIC_HEADERS ${header})
    list(APPEND TUTTI_PUBLIC_HEADER_FILES ${root}/${header})
    get_filename_component(header_dir ${header} DIRECTORY)
    install(FILES ${root}/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tutti/${header_dir}
            COMPONENT dev)
  endforeach()
endforeach()

set(TUTTI_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/tutti)

foreach(set_name Performance Sound Render)
  string(TOUPPER ${set_name} upper)
  set(export_name tutti${set_name}Targets)
  if(set_name STREQUAL "Performance")
    set(export_name tuttiTargets)
  endif()
  set(targets ${TUTTI_${upper}_TARGETS})
  if(set_name STREQUAL "Render")
    list(APPEND targets tutti_all)
  endif()
  install(TARGETS ${targets} EXPORT ${export_name}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT dev)
  install(EXPORT ${export_name} NAMESPACE tutti:: DESTINATION ${TUTTI_INSTALL_CMAKEDIR}
          COMPONENT dev)
endforeach()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tuttiConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/package/tuttiConfig.cmake
                              INSTALL_DESTINATION ${TUTTI_INSTALL_CMAKEDIR}
                              PATH_VARS TUTTI_INSTALL_CONTENT_DIR TUTTI_INSTALL_ASSET_DIR)
# 0.x: a minor version may break the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/tuttiConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/tuttiConfig.cmake
              ${PROJECT_BINARY_DIR}/package/tuttiConfigVersion.cmake
        DESTINATION ${TUTTI_INSTALL_CMAKEDIR} COMPONENT dev)
# The licence goes with every installation (README.md's "Licence": the dependencies' own).
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
