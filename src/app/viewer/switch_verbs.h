#pragma once
// The script's verbs that flip, step or nudge what the viewer shows, the lines most keys are
// bound to (shortcuts.cpp; rows of the verb table in script_verbs.cpp):
//   toggle NAME            a switch of `set` (ambient, ..., shadows, panel, inspector, help) to
//                          its other value, saying what it did as the key always has
//   cycle NAME             a choice of `set` (fog) to its next value
//   attenuation toggle|inverse-square|classroom   f_att of every light: 1/d², or the classroom's
//                          1/(c0 + c1·d + c2·d²)
//   exposure +EV | -EV     the exposure moved by that many stops
//   interface larger|smaller   the interface's size by a step of kUiScaleStep
#include <string>

#include "app/script/script.h"

namespace luz::app {

class Viewer;

std::string check_toggle(const ScriptCommand& command);
bool run_toggle(Viewer& viewer, const ScriptCommand& command, std::string& error);
std::string check_cycle(const ScriptCommand& command);
bool run_cycle(Viewer& viewer, const ScriptCommand& command, std::string& error);
std::string check_attenuation(const ScriptCommand& command);
bool run_attenuation(Viewer& viewer, const ScriptCommand& command, std::string& error);
std::string check_exposure_step(const ScriptCommand& command);
bool run_exposure_step(Viewer& viewer, const ScriptCommand& command, std::string& error);
std::string check_interface(const ScriptCommand& command);
bool run_interface(Viewer& viewer, const ScriptCommand& command, std::string& error);

}  // namespace luz::app
