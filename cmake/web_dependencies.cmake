# The web page's dependencies (docs/web.md), under Emscripten: the same names the desktop's
# find_package() gives, so src/core, src/io, src/gl and src/local link them unchanged.
# - Header-only packages (GLM, fmt, nlohmann-json, tinygltf, stb) are Debian's headers, seen
#   through a folder of links in the build tree: adding /usr/include itself would put the
#   desktop's C library in front of Emscripten's.
# - GL/glcorearb.h (the table of gl/functions.h: types, enums and function pointer types only)
#   is Debian's too (libgl-dev); Emscripten ships the ES headers only.
# - libdeflate (the PNG writer) is compiled from Debian's source (`apt-get source libdeflate`,
#   unpacked by ./setup.sh web into LUZ_WEB_SOURCES).
# - Embree (the ray tracers, the rays form factors) is compiled from Debian's source too
#   (web_embree.cmake).
# - OpenEXR is not read in the page (tinyexr needs zlib, which Emscripten only downloads).
# Where the page's packed files (shaders, scenes, catalogues) are in its file system.
set(LUZ_WEB_DATA_DIR /luz)

set(LUZ_WEB_SOURCES "${PROJECT_SOURCE_DIR}/build-web/sources" CACHE PATH
    "Where ./setup.sh web unpacks the Debian source packages the page compiles")

set(luz_web_include ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${luz_web_include}/GL)
foreach(entry glm fmt nlohmann tiny_gltf.h stb libdeflate.h GL/glcorearb.h)
  if(NOT EXISTS /usr/include/${entry})
    message(FATAL_ERROR "the web build needs /usr/include/${entry} (./setup.sh installs its package)")
  endif()
  file(CREATE_LINK /usr/include/${entry} ${luz_web_include}/${entry} SYMBOLIC)
endforeach()

# Threads or not (docs/web.md, "Threads"): the page is built twice from the same sources. With
# threads (the default) it is luz.html's luz.js, which needs a cross-origin isolated page; without
# (LUZ_WEB_THREADS=OFF, a second build tree that src/app/web makes of this one) it is
# luz-1thread.js, which any page can start, every loop and job on the browser's main thread.
option(LUZ_WEB_THREADS "Build the page with threads (-pthread); OFF: the one-thread page, luz-1thread.js" ON)

# The flags every object of the page is compiled with, and the page linked with (every target of
# the web build links this):
# - C++ exceptions are off by default in Emscripten (a throw aborts); Luz reports bad input with
#   them, and tinygltf's JSON reader uses them.
# - -pthread: WebAssembly threads share one memory, and the linker refuses to make that memory
#   shared when one object was compiled without atomics (and refuses objects with atomics in a
#   memory that is not shared): every object of a build has it, or none. Growing a shared memory
#   slows JavaScript's reads of it a little (the page's only ones are the picture it hands to
#   WebGL): the linker's warning about that is silenced.
# - -msimd128: WebAssembly's 128-bit vectors, which Embree's kernels need already (every browser
#   with WebGL 2 and threads has them). With them the compiler vectorises Luz's own loops as it does
#   natively with SSE2 (the tracer's shading lanes, hit_lanes.h): Whitted's scene at 1024x1024
#   took 322-327 ms of one core in node against 374-376 ms without (docs/web.md).
set(luz_web_thread_flag)
if(LUZ_WEB_THREADS)
  set(luz_web_thread_flag -pthread)
endif()
add_library(luz_web_flags INTERFACE)
target_compile_options(luz_web_flags INTERFACE -fexceptions -msimd128 ${luz_web_thread_flag})
target_link_options(luz_web_flags INTERFACE -fexceptions ${luz_web_thread_flag} -Wno-pthreads-mem-growth)

add_library(luz_web_headers INTERFACE)
target_include_directories(luz_web_headers SYSTEM INTERFACE ${luz_web_include})
target_link_libraries(luz_web_headers INTERFACE luz_web_flags)

add_library(glm::glm ALIAS luz_web_headers)
add_library(nlohmann_json::nlohmann_json ALIAS luz_web_headers)

add_library(luz_web_fmt INTERFACE)
target_link_libraries(luz_web_fmt INTERFACE luz_web_headers)
target_compile_definitions(luz_web_fmt INTERFACE FMT_HEADER_ONLY=1)
add_library(fmt::fmt ALIAS luz_web_fmt)

# tinygltf's implementation in one file; the loader gives it its own image reader.
set(luz_tinygltf_source ${CMAKE_BINARY_DIR}/tinygltf_implementation.cpp)
file(WRITE ${luz_tinygltf_source}.in "#define TINYGLTF_IMPLEMENTATION\n#include <tiny_gltf.h>\n")
configure_file(${luz_tinygltf_source}.in ${luz_tinygltf_source} COPYONLY)
add_library(luz_web_tinygltf STATIC ${luz_tinygltf_source})
target_link_libraries(luz_web_tinygltf PUBLIC luz_web_headers)
target_compile_definitions(luz_web_tinygltf PUBLIC TINYGLTF_NO_STB_IMAGE TINYGLTF_NO_STB_IMAGE_WRITE)
add_library(TinyGLTF::TinyGLTF ALIAS luz_web_tinygltf)

# stb_truetype (the labels of src/app/common's plots), whose implementation the desktop takes
# from Debian's libstb, compiled from its header; its header by bare name, as libstb's .pc gives.
set(luz_stb_source ${CMAKE_BINARY_DIR}/stb_truetype_implementation.c)
file(WRITE ${luz_stb_source}.in "#define STB_TRUETYPE_IMPLEMENTATION\n#include <stb_truetype.h>\n")
configure_file(${luz_stb_source}.in ${luz_stb_source} COPYONLY)
add_library(luz_web_stb STATIC ${luz_stb_source})
target_include_directories(luz_web_stb SYSTEM PUBLIC ${luz_web_include}/stb)
target_link_libraries(luz_web_stb PRIVATE luz_web_flags)
add_library(PkgConfig::Stb ALIAS luz_web_stb)

file(GLOB luz_libdeflate_sources ${LUZ_WEB_SOURCES}/libdeflate-*/lib/*.c)
if(NOT luz_libdeflate_sources)
  message(FATAL_ERROR "no libdeflate sources in ${LUZ_WEB_SOURCES}: ./setup.sh web unpacks them")
endif()
add_library(luz_web_libdeflate STATIC ${luz_libdeflate_sources})
target_include_directories(luz_web_libdeflate PUBLIC ${luz_web_include})
target_link_libraries(luz_web_libdeflate PRIVATE luz_web_flags)
add_library(PkgConfig::libdeflate ALIAS luz_web_libdeflate)

include(${CMAKE_CURRENT_LIST_DIR}/web_embree.cmake)

# The viewer's: Dear ImGui, GLFW, CLI11.
include(${CMAKE_CURRENT_LIST_DIR}/web_viewer.cmake)
