# The viewer's own dependencies in the page (docs/web.md), under the desktop's target names, so
# that src/app links them unchanged:
# - Dear ImGui 1.86: its core .cpp files from Debian's source package (`apt-get source imgui`,
#   unpacked by ./setup.sh web into LUZ_WEB_SOURCES; the desktop links Debian's libimgui-dev),
#   and its GLFW and OpenGL 3 backends from the same tree, the renderer in its GL ES 3 dialect
#   ("#version 300 es", WebGL 2's). Its fonts' rasteriser is the tree's own stb_truetype.
# - GLFW: Emscripten's built-in port (-sUSE_GLFW=3 at the link; its header is in Emscripten's
#   system headers), a GLFW 3.2 on the page's canvas.
# - CLI11 (luz render's flags, which the cli library parses): Debian's headers.
file(GLOB luz_imgui_source LIST_DIRECTORIES true ${LUZ_WEB_SOURCES}/imgui-1.*)
if(NOT luz_imgui_source OR NOT EXISTS ${luz_imgui_source}/imgui.cpp)
  message(FATAL_ERROR "no Dear ImGui sources in ${LUZ_WEB_SOURCES}: ./setup.sh web unpacks them")
endif()
add_library(luz_web_imgui STATIC
  ${luz_imgui_source}/imgui.cpp
  ${luz_imgui_source}/imgui_draw.cpp
  ${luz_imgui_source}/imgui_tables.cpp
  ${luz_imgui_source}/imgui_widgets.cpp)
target_include_directories(luz_web_imgui SYSTEM PUBLIC ${luz_imgui_source})
target_link_libraries(luz_web_imgui PUBLIC luz_web_headers)
add_library(PkgConfig::ImGui ALIAS luz_web_imgui)
set(LUZ_IMGUI_BACKEND_DIR ${luz_imgui_source}/backends)
set(ImGui_INCLUDEDIR ${luz_imgui_source})

add_library(luz_web_glfw INTERFACE)
target_link_options(luz_web_glfw INTERFACE -sUSE_GLFW=3)
add_library(glfw ALIAS luz_web_glfw)

if(NOT EXISTS /usr/include/CLI/CLI.hpp)
  message(FATAL_ERROR "the web build needs /usr/include/CLI (libcli11-dev; ./setup.sh installs it)")
endif()
file(CREATE_LINK /usr/include/CLI ${luz_web_include}/CLI SYMBOLIC)
add_library(CLI11::CLI11 ALIAS luz_web_headers)
