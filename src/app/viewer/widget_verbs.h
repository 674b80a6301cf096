#pragma once
// The script's verbs that address what is on screen by name rather than by window coordinates
// (rows of the verb table in script_verbs.cpp):
//   click-widget "LABEL"    a click at the centre of the panel widget of that label
//                           (widget_registry.h), through the same path as `click X Y`
//   dump-widgets FILE.json  every named widget's label and rectangle, in window coordinates
//   click-picture X Y       a click on pixel (X, Y) of the picture (row 0 at the top), wherever
//                           the panel leaves the picture: the pixel `luz render --ray-tree X,Y` reads
//   click-picture X% Y%     a click at those fractions of the square as high as the picture,
//                           centred in it (the camera's vertical field of view spans it at any
//                           width): the same object at any window size and UI scale (a lesson's)
// and the waits for a state, each with a cap on the frames it may take:
//   wait-until CONDITION FRAMES   trace-done | radiosity-done; the script fails when the
//                                 condition does not hold within FRAMES frames
#include <string>

#include "app/script/script.h"

namespace luz::app {

class Viewer;

std::string check_click_widget(const ScriptCommand& command);
bool run_click_widget(Viewer& viewer, const ScriptCommand& command, std::string& error);
bool run_dump_widgets(Viewer& viewer, const ScriptCommand& command, std::string& error);
std::string check_click_picture(const ScriptCommand& command);
bool run_click_picture(Viewer& viewer, const ScriptCommand& command, std::string& error);

std::string check_wait_until(const ScriptCommand& command);
// Whether `condition` (a word check_wait_until accepts) holds in the viewer now.
bool condition_holds(Viewer& viewer, const std::string& condition);

}  // namespace luz::app
