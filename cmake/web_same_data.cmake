# cmake -DFIRST=luz.data -DSECOND=luz-1thread.data -P web_same_data.cmake: the one-thread page
# loads luz.data in place of its own .data (luz.html), which is right only when the two packed
# the same files at the same places, byte for byte.
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${FIRST} ${SECOND} RESULT_VARIABLE different)
if(different)
  message(FATAL_ERROR "${SECOND} differs from ${FIRST}: the one-thread page cannot load luz.data in its place")
endif()
