# Embree 3.13.5 for the web page, compiled from Debian's source package (`apt-get source embree`,
# whose orig tarball ./setup.sh web unpacks into LUZ_WEB_SOURCES), as its own CMake project: its
# compiler flags stay its own. Under Emscripten its build files already choose -pthread,
# -msimd128 and the SSE2 kernels on Emscripten's SSE emulation; here it is told to build a static
# library with its own task scheduler (oneTBB has no WebAssembly build), without ISPC, and only
# the triangles Luz traces. Ray packets stay on: rtcIntersect1M (the wavefront's streams) needs
# them. The result is the target `embree`, the name the desktop's find_package(embree 3) gives.
file(GLOB luz_embree_source LIST_DIRECTORIES true ${LUZ_WEB_SOURCES}/embree-3.*)
if(NOT luz_embree_source OR NOT EXISTS ${luz_embree_source}/include/embree3/rtcore.h)
  message(FATAL_ERROR "no Embree sources in ${LUZ_WEB_SOURCES}: ./setup.sh web unpacks them")
endif()

# Without threads (LUZ_WEB_THREADS=OFF), its build files' -pthread is dropped from every compile
# line by a launcher in front of the compiler (web_without_pthread.sh), its sources unchanged;
# Luz then asks its devices for one thread (raytracing/embree_scene.cpp), and its task scheduler
# starts none.
set(luz_embree_launchers ${CMAKE_CXX_COMPILER_LAUNCHER})
if(NOT LUZ_WEB_THREADS)
  list(PREPEND luz_embree_launchers ${CMAKE_CURRENT_LIST_DIR}/web_without_pthread.sh)
endif()
list(JOIN luz_embree_launchers "|" luz_embree_launchers)

include(ExternalProject)
set(luz_embree_build ${CMAKE_BINARY_DIR}/embree)
# Its static libraries: the API and kernels, and the five it splits its common code into.
set(luz_embree_libraries)
foreach(library embree3 lexers sys math simd tasking)
  list(APPEND luz_embree_libraries ${luz_embree_build}/lib${library}.a)
endforeach()
ExternalProject_Add(luz_web_embree_build
  SOURCE_DIR ${luz_embree_source}
  BINARY_DIR ${luz_embree_build}
  LIST_SEPARATOR |
  CMAKE_ARGS
    -DCMAKE_TOOLCHAIN_FILE=${CMAKE_TOOLCHAIN_FILE}
    -DCMAKE_BUILD_TYPE=Release
    # Its sources' own warnings (unused fields, SSE flags the WebAssembly target ignores) are not
    # ours to fix: silenced (its build files drop the flags given them unless told not to), so that
    # the page's build shows only Luz's.
    -DEMBREE_IGNORE_CMAKE_CXX_FLAGS=OFF -DCMAKE_CXX_FLAGS=-w
    -DCMAKE_C_COMPILER_LAUNCHER=${CMAKE_C_COMPILER_LAUNCHER}
    -DCMAKE_CXX_COMPILER_LAUNCHER=${luz_embree_launchers}
    -DEMBREE_STATIC_LIB=ON
    -DEMBREE_TASKING_SYSTEM=INTERNAL
    -DEMBREE_ISPC_SUPPORT=OFF
    -DEMBREE_MAX_ISA=SSE2
    -DEMBREE_TUTORIALS=OFF
    -DEMBREE_GEOMETRY_TRIANGLE=ON
    -DEMBREE_GEOMETRY_QUAD=OFF
    -DEMBREE_GEOMETRY_CURVE=OFF
    -DEMBREE_GEOMETRY_SUBDIVISION=OFF
    -DEMBREE_GEOMETRY_USER=OFF
    -DEMBREE_GEOMETRY_INSTANCE=OFF
    -DEMBREE_GEOMETRY_GRID=OFF
    -DEMBREE_GEOMETRY_POINT=OFF
  BUILD_BYPRODUCTS ${luz_embree_libraries}
  INSTALL_COMMAND "")

# Its headers are the source tree's include/ (rtcore_config.h is written there by its configure).
add_library(embree INTERFACE)
add_dependencies(embree luz_web_embree_build)
target_include_directories(embree SYSTEM INTERFACE ${luz_embree_source}/include)
target_link_libraries(embree INTERFACE ${luz_embree_libraries} luz_web_flags)
