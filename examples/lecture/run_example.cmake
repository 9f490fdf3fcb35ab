# Runs one lecture example and checks its PNG: it must exist, have the expected size and not
# be blank; with MESA_EXAMPLE and COMPARE, the same program built against Mesa's libOSMesa
# runs too and gl_compare holds the two images to the conformance bar.
#   cmake -DEXAMPLE=... -DOUTPUT=... -DCHECK=... -DWIDTH=... -DHEIGHT=... [-DARGS=a;b]
#         [-DMESA_EXAMPLE=... -DCOMPARE=...] -P run_example.cmake
file(REMOVE ${OUTPUT})
get_filename_component(dir ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
execute_process(COMMAND ${EXAMPLE} ${OUTPUT} ${ARGS} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXAMPLE} failed (exit status ${rc})")
endif()
if(NOT EXISTS ${OUTPUT})
  message(FATAL_ERROR "${EXAMPLE} wrote no ${OUTPUT}")
endif()
execute_process(COMMAND ${CHECK} ${OUTPUT} ${WIDTH} ${HEIGHT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OUTPUT} failed the check")
endif()

if(MESA_EXAMPLE AND COMPARE)
  string(REGEX REPLACE "\\.png$" "" stem ${OUTPUT})
  set(mesa_png ${stem}.mesa.png)
  file(REMOVE ${mesa_png} ${stem}.diff.png)
  execute_process(COMMAND ${MESA_EXAMPLE} ${mesa_png} ${ARGS} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${MESA_EXAMPLE} failed (exit status ${rc})")
  endif()
  get_filename_component(name ${OUTPUT} NAME_WE)
  execute_process(COMMAND ${COMPARE} ${mesa_png} ${OUTPUT} --name ${name} --diff ${stem}.diff.png
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${OUTPUT} differs from Mesa's ${mesa_png}")
  endif()
endif()
