# Finds shadowlab's dependencies and gives each one target of ours, whatever provided it:
#
#   shadowlab::imgui     Dear ImGui with its GLFW and OpenGL3 backends (>= 1.86)
#   shadowlab::stb       stb_image_write (the implementation comes with it)
#   shadowlab::tinygltf  tinygltf (the implementation comes with it)
#   shadowlab::embree    Embree 3 or 4; SHADOWLAB_EMBREE_MAJOR says which
#   shadowlab::epoxy     libepoxy (GL entry points under GLX, WGL, CGL and EGL)
#   shadowlab::md4c      md4c, the Markdown parser of the panel's lab texts
#   shadowlab::archive   libarchive, which unpacks submitted zip and tar archives (`shadowlab grade`)
#
# Each is looked up first as the CMake package its project exports (what vcpkg, Homebrew and most Linux
# distributions install), then through Debian's pkg-config files or headers as the fallback. glfw3,
# glm, nlohmann_json, CLI11 and GTest are CMake packages everywhere and are found directly.
include_guard(GLOBAL)

find_package(PkgConfig QUIET)

function(shadowlab_interface name)
  add_library(shadowlab_dep_${name} INTERFACE)
  add_library(shadowlab::${name} ALIAS shadowlab_dep_${name})
endfunction()

# Links shadowlab::<name> to pkg-config's <module> when pkg-config finds it; <found_var> says whether.
function(shadowlab_link_pkg name module found_var)
  set(found FALSE)
  if(PkgConfig_FOUND)
    pkg_check_modules(SHADOWLAB_PKG_${name} QUIET IMPORTED_TARGET ${module})
    if(TARGET PkgConfig::SHADOWLAB_PKG_${name})
      target_link_libraries(shadowlab_dep_${name} INTERFACE PkgConfig::SHADOWLAB_PKG_${name})
      set(found TRUE)
    endif()
  endif()
  set(${found_var} ${found} PARENT_SCOPE)
endfunction()

# A library that ships headers only needs its implementation compiled once: core/third_party.cpp
# does it for the ones listed here (compile definitions SHADOWLAB_<NAME>_IMPLEMENTATION).
set(SHADOWLAB_THIRD_PARTY_DEFS "")

# --- GLFW, GLM, JSON, CLI11: CMake packages everywhere ---------------------------------------------------
find_package(glfw3 3.3 REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)

# --- Dear ImGui ------------------------------------------------------------------------------------------
# vcpkg: `imgui[glfw-binding,opengl3-binding]` exports imgui::imgui with the backends compiled in and
# their headers beside imgui.h. Debian: pkg-config `imgui`, libimgui holds the backends, their headers
# are in <imgui/backends/>, added to the include path so `#include <imgui_impl_glfw.h>` works for both.
shadowlab_interface(imgui)
find_package(imgui CONFIG QUIET)
if(TARGET imgui::imgui)
  target_link_libraries(shadowlab_dep_imgui INTERFACE imgui::imgui)
  set(SHADOWLAB_IMGUI_FROM "CMake package imgui (${imgui_VERSION})")
  set(SHADOWLAB_IMGUI_VERSION "${imgui_VERSION}")
elseif(PkgConfig_FOUND)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
  pkg_get_variable(IMGUI_INCLUDEDIR imgui includedir)
  target_link_libraries(shadowlab_dep_imgui INTERFACE PkgConfig::IMGUI glfw ${CMAKE_DL_LIBS})
  target_include_directories(shadowlab_dep_imgui INTERFACE "${IMGUI_INCLUDEDIR}/backends")
  set(SHADOWLAB_IMGUI_FROM "pkg-config imgui (${IMGUI_VERSION})")
  set(SHADOWLAB_IMGUI_VERSION "${IMGUI_VERSION}")
else()
  message(FATAL_ERROR "Dear ImGui not found: install vcpkg's imgui[glfw-binding,opengl3-binding] "
                      "(see vcpkg.json) or Debian's libimgui-dev")
endif()

# --- stb_image_write -------------------------------------------------------------------------------------
# Debian: pkg-config `stb`, a library holding the implementations. vcpkg: headers only (find_package(Stb)),
# on macOS too: Homebrew has no stb, the README's Homebrew recipe takes vcpkg's (with ImGui and tinygltf).
shadowlab_interface(stb)
shadowlab_link_pkg(stb stb _found)
if(_found)
  set(SHADOWLAB_STB_FROM "pkg-config stb")
else()
  find_package(Stb QUIET)
  find_path(SHADOWLAB_STB_INCLUDE_DIR stb_image_write.h HINTS ${Stb_INCLUDE_DIR} PATH_SUFFIXES stb)
  if(NOT SHADOWLAB_STB_INCLUDE_DIR)
    message(FATAL_ERROR "stb not found: install vcpkg's stb or Debian's libstb-dev")
  endif()
  target_include_directories(shadowlab_dep_stb INTERFACE "${SHADOWLAB_STB_INCLUDE_DIR}")
  list(APPEND SHADOWLAB_THIRD_PARTY_DEFS SHADOWLAB_STB_IMPLEMENTATION)
  set(SHADOWLAB_STB_FROM "headers in ${SHADOWLAB_STB_INCLUDE_DIR}")
endif()

# --- tinygltf --------------------------------------------------------------------------------------------
# Its own CMake install (Debian's libtinygltf-dev) exports TinyGLTF::TinyGLTF, a compiled library. vcpkg
# ships the header only: the implementation is then compiled here.
shadowlab_interface(tinygltf)
find_package(TinyGLTF CONFIG QUIET)
if(TARGET TinyGLTF::TinyGLTF)
  target_link_libraries(shadowlab_dep_tinygltf INTERFACE TinyGLTF::TinyGLTF)
  set(SHADOWLAB_TINYGLTF_FROM "CMake package TinyGLTF")
else()
  find_path(SHADOWLAB_TINYGLTF_INCLUDE_DIR tiny_gltf.h PATH_SUFFIXES tinygltf)
  if(NOT SHADOWLAB_TINYGLTF_INCLUDE_DIR)
    message(FATAL_ERROR "tinygltf not found: install vcpkg's tinygltf or Debian's libtinygltf-dev")
  endif()
  target_include_directories(shadowlab_dep_tinygltf INTERFACE "${SHADOWLAB_TINYGLTF_INCLUDE_DIR}")
  target_link_libraries(shadowlab_dep_tinygltf INTERFACE nlohmann_json::nlohmann_json shadowlab::stb)
  list(APPEND SHADOWLAB_THIRD_PARTY_DEFS SHADOWLAB_TINYGLTF_IMPLEMENTATION)
  set(SHADOWLAB_TINYGLTF_FROM "header in ${SHADOWLAB_TINYGLTF_INCLUDE_DIR}")
endif()

# --- Embree 3 or 4 ---------------------------------------------------------------------------------------
# Both export the CMake package `embree` with the target `embree`. Embree 4 first (Debian 13, Ubuntu 24.04,
# Homebrew, vcpkg ship only 4); oracle/oracle.cpp holds the one seam between their APIs.
shadowlab_interface(embree)
set(SHADOWLAB_EMBREE "AUTO" CACHE STRING "Embree major version to use: AUTO (4, else 3), 3 or 4")
set_property(CACHE SHADOWLAB_EMBREE PROPERTY STRINGS AUTO 3 4)
if(SHADOWLAB_EMBREE STREQUAL "AUTO" OR SHADOWLAB_EMBREE STREQUAL "4")
  find_package(embree 4 CONFIG QUIET)
endif()
if(NOT embree_FOUND AND NOT SHADOWLAB_EMBREE STREQUAL "4")
  find_package(embree 3 CONFIG QUIET)
endif()
if(NOT embree_FOUND)
  message(FATAL_ERROR "Embree 3 or 4 not found (SHADOWLAB_EMBREE=${SHADOWLAB_EMBREE}): install vcpkg's embree, "
                      "Homebrew's embree or Debian's libembree-dev")
endif()
string(REGEX MATCH "^[0-9]+" SHADOWLAB_EMBREE_MAJOR "${embree_VERSION}")
target_link_libraries(shadowlab_dep_embree INTERFACE embree)
target_compile_definitions(shadowlab_dep_embree INTERFACE SHADOWLAB_EMBREE_MAJOR=${SHADOWLAB_EMBREE_MAJOR})

# --- libepoxy --------------------------------------------------------------------------------------------
# pkg-config everywhere it is packaged (Debian, Homebrew, vcpkg's pkgconf); a plain header and library
# search otherwise.
shadowlab_interface(epoxy)
shadowlab_link_pkg(epoxy epoxy _found)
if(NOT _found)
  find_path(SHADOWLAB_EPOXY_INCLUDE_DIR epoxy/gl.h)
  find_library(SHADOWLAB_EPOXY_LIBRARY NAMES epoxy epoxy-0)
  if(NOT SHADOWLAB_EPOXY_INCLUDE_DIR OR NOT SHADOWLAB_EPOXY_LIBRARY)
    message(FATAL_ERROR "libepoxy not found: install vcpkg's libepoxy, Homebrew's libepoxy or Debian's libepoxy-dev")
  endif()
  target_include_directories(shadowlab_dep_epoxy INTERFACE "${SHADOWLAB_EPOXY_INCLUDE_DIR}")
  target_link_libraries(shadowlab_dep_epoxy INTERFACE "${SHADOWLAB_EPOXY_LIBRARY}")
endif()

# --- md4c ------------------------------------------------------------------------------------------------
# pkg-config first here: Debian 12's md4cConfig.cmake (libmd4c-dev) stops configuring with a fatal error
# unless libmd4c-html0-dev is installed too (it checks for libmd4c-html's file). Then the CMake package
# md4c::md4c (vcpkg, Homebrew, or Debian with both packages).
shadowlab_interface(md4c)
shadowlab_link_pkg(md4c md4c _found)
if(NOT _found)
  find_package(md4c CONFIG REQUIRED)
  target_link_libraries(shadowlab_dep_md4c INTERFACE md4c::md4c)
endif()

# --- libarchive -------------------------------------------------------------------------------------------
# CMake's own FindLibArchive (LibArchive::LibArchive, CMake >= 3.17) finds Debian's and vcpkg's. Homebrew's
# is keg-only (macOS has a libarchive of its own, without its headers), so it is found where the README's
# recipe says: -DLibArchive_ROOT=$(brew --prefix libarchive).
shadowlab_interface(archive)
find_package(LibArchive 3)
if(NOT LibArchive_FOUND)
  message(FATAL_ERROR "libarchive 3 not found: install vcpkg's libarchive, Debian's libarchive-dev, or Homebrew's "
                      "libarchive, which is keg-only: configure with -DLibArchive_ROOT=$(brew --prefix libarchive)")
endif()
target_link_libraries(shadowlab_dep_archive INTERFACE LibArchive::LibArchive)

# --- EGL (headless GL without a display; Linux) ----------------------------------------------------------
# Where EGL is missing, or SHADOWLAB_EGL is OFF, headless runs use a hidden GLFW window instead.
set(_shadowlab_egl_default OFF)
if(UNIX AND NOT APPLE)
  find_package(OpenGL QUIET COMPONENTS EGL)
  if(OpenGL_EGL_FOUND)
    set(_shadowlab_egl_default ON)
  endif()
endif()
option(SHADOWLAB_EGL "Headless runs through EGL with no display (Linux); OFF: a hidden GLFW window" ${_shadowlab_egl_default})
if(SHADOWLAB_EGL)
  find_package(OpenGL REQUIRED COMPONENTS EGL)
  set(_shadowlab_headless "EGL")
else()
  set(_shadowlab_headless "a hidden GLFW window")
endif()

message(STATUS "shadowlab: ImGui from ${SHADOWLAB_IMGUI_FROM}; stb from ${SHADOWLAB_STB_FROM}; "
               "tinygltf from ${SHADOWLAB_TINYGLTF_FROM}; Embree ${embree_VERSION}; headless GL through "
               "${_shadowlab_headless}")
