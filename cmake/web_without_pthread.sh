#!/bin/sh
# A compiler launcher for Embree's build in the one-thread page (web_embree.cmake): runs the
# command it is given (the next launcher, or the compiler) without the -pthread that Embree's
# build files add under Emscripten, so that its objects fit a module without shared memory.
for argument in "$@"; do
  shift
  [ "$argument" = -pthread ] || set -- "$@" "$argument"
done
exec "$@"
