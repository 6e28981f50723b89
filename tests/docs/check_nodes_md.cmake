# docs/nodes.md is `procex nodes --markdown`: fails when a node's declaration
# changed and the file was not regenerated.
execute_process(COMMAND ${PROCEX} nodes --markdown OUTPUT_VARIABLE now RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "procex nodes --markdown failed (${rc})")
endif()
file(READ ${NODES_MD} saved)
if(NOT now STREQUAL saved)
  message(FATAL_ERROR "docs/nodes.md is stale: regenerate it with `build/app/cli/procex nodes --markdown > docs/nodes.md`")
endif()
