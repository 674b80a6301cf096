#pragma once
// The options tables several models share (option_row.h): the local models' LocalOptions (whose
// term switches the tracers and the hybrid take too), the Whitted tracer's rt::WhittedOptions
// (the hybrid's too) and RadiosityOptions (the hybrid's too). A model's own options are a table
// in its folder (the path tracer's path_options.h); the registry's entries name the tables each
// model takes.
#include "app/common/option_row.h"
#include "local/local_options.h"
#include "radiosity/radiosity_options.h"
#include "raytracing/whitted_options.h"

namespace luz::app {

const OptionTable& local_table();      // over LocalOptions
const OptionTable& whitted_table();    // over rt::WhittedOptions
const OptionTable& radiosity_table();  // over RadiosityOptions

}  // namespace luz::app
