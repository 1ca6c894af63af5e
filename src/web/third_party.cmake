# The shader translator's compilers for the browser build: glslang and
# SPIRV-Cross, which Debian ships as libraries for the desktop only. The
# build brings Debian's source packages into the build folder with
# `apt-get source` (tools/install-deps.sh adds the deb-src entry and
# dpkg-dev) and compiles the parts the translator needs with Emscripten.
# Nothing third-party is in the source tree.
#
# The versions are the desktop's (glslang-dev 12.0.0, spirv-cross
# 2021.01.15+1.3.239.0): the page translates exactly as `glimmer check --web`.
set(third_party ${CMAKE_BINARY_DIR}/third_party)
file(MAKE_DIRECTORY ${third_party})

# Fetches a Debian source package into the build folder once, at configure
# time; `dir` is the folder it unpacks to.
function(glimmer_debian_source package dir)
  if(EXISTS ${third_party}/${dir})
    return()
  endif()
  message(STATUS "apt-get source ${package} (into ${third_party})")
  execute_process(COMMAND apt-get source -qq ${package}
                  WORKING_DIRECTORY ${third_party}
                  RESULT_VARIABLE failed OUTPUT_QUIET ERROR_VARIABLE why)
  if(failed OR NOT EXISTS ${third_party}/${dir})
    message(FATAL_ERROR "apt-get source ${package} failed (run tools/install-deps.sh: it adds "
                        "Debian's deb-src entry and dpkg-dev):\n${why}")
  endif()
endfunction()

glimmer_debian_source(glslang=12.0.0-2 glslang-12.0.0)
glimmer_debian_source(spirv-cross=2021.01.15+1.3.239.0-1 spirv-cross-2021.01.15+1.3.239.0)

# glslang: the front end and its SPIR-V generator, no optimizer, no HLSL,
# no tools.
set(ENABLE_OPT OFF CACHE BOOL "" FORCE)
set(ENABLE_HLSL OFF CACHE BOOL "" FORCE)
set(ENABLE_GLSLANG_BINARIES OFF CACHE BOOL "" FORCE)
set(ENABLE_CTEST OFF CACHE BOOL "" FORCE)
set(ENABLE_PCH OFF CACHE BOOL "" FORCE)
set(ENABLE_SPVREMAPPER OFF CACHE BOOL "" FORCE)
set(BUILD_EXTERNAL OFF CACHE BOOL "" FORCE)
set(SKIP_GLSLANG_INSTALL ON CACHE BOOL "" FORCE)
add_subdirectory(${third_party}/glslang-12.0.0 ${third_party}/glslang-build EXCLUDE_FROM_ALL)
# The default resource limits live with glslang's command-line tool, which
# is off: the one file, compiled here.
add_library(web_glslang_limits STATIC ${third_party}/glslang-12.0.0/StandAlone/ResourceLimits.cpp)
target_include_directories(web_glslang_limits PUBLIC ${third_party}/glslang-12.0.0)
# The desktop's names for them (Debian's glslangConfig.cmake).
add_library(glslang::glslang ALIAS glslang)
add_library(glslang::SPIRV ALIAS SPIRV)
add_library(glslang::glslang-default-resource-limits ALIAS web_glslang_limits)
# <glslang/Public/...> and <glslang/SPIRV/...>, as Debian installs them
# (the source tree keeps SPIRV/ beside glslang/, not in it).
file(MAKE_DIRECTORY ${web_include}/glslang)
foreach(entry Public Include MachineIndependent)
  file(CREATE_LINK ${third_party}/glslang-12.0.0/glslang/${entry} ${web_include}/glslang/${entry} SYMBOLIC)
endforeach()
file(CREATE_LINK ${third_party}/glslang-12.0.0/SPIRV ${web_include}/glslang/SPIRV SYMBOLIC)
target_include_directories(glslang INTERFACE ${web_include})

# SPIRV-Cross: the core and the GLSL back end, as static libraries.
set(SPIRV_CROSS_CLI OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_ENABLE_TESTS OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_ENABLE_HLSL OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_ENABLE_MSL OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_ENABLE_CPP OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_ENABLE_REFLECT OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_ENABLE_C_API OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_ENABLE_UTIL OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_SHARED OFF CACHE BOOL "" FORCE)
set(SPIRV_CROSS_STATIC ON CACHE BOOL "" FORCE)
set(SPIRV_CROSS_SKIP_INSTALL ON CACHE BOOL "" FORCE)
add_subdirectory(${third_party}/spirv-cross-2021.01.15+1.3.239.0 ${third_party}/spirv-cross-build EXCLUDE_FROM_ALL)
# <spirv_glsl.hpp>, as Debian's spirv_cross_glsl target gives it.
target_include_directories(spirv-cross-core INTERFACE ${third_party}/spirv-cross-2021.01.15+1.3.239.0)

# Dear ImGui for the page's panel: the desktop links Debian's libimgui
# (1.86); the page compiles the same version's core and its OpenGL 3
# backend (which takes its GLSL ES 3.00 path under Emscripten) from the
# source package. The page's input comes from the canvas (web_view_input.cpp),
# not from a GLFW port: see docs/browser.md.
glimmer_debian_source(imgui=1.86+ds-1 imgui-1.86+ds)
set(imgui_dir ${third_party}/imgui-1.86+ds)
add_library(web_imgui STATIC ${imgui_dir}/imgui.cpp ${imgui_dir}/imgui_draw.cpp ${imgui_dir}/imgui_tables.cpp
            ${imgui_dir}/imgui_widgets.cpp ${imgui_dir}/backends/imgui_impl_opengl3.cpp)
# <imgui.h> and <backends/imgui_impl_opengl3.h>, as the desktop includes them.
target_include_directories(web_imgui SYSTEM PUBLIC ${imgui_dir})
