# Runs one conformance program: Mesa's build (the reference, llvmpipe as the test's environment
# says), shadelab-gl's build, then gl_compare. Outputs in OUT_DIR: NAME.mesa.png,
# NAME.shadelab.png and, on failure, NAME.diff.png.
#
#   cmake -DNAME=... -DOUT_DIR=... -DMESA_EXE=... [-DSHADELAB_EXE=...] -DCOMPARE=...
#         [-DCOMPARE_ARGS=...] [-DSELFCHECK=ON] [-DVALUES=ON -DVALUES_COMPARE=... [-DVALUES_REL=R]]
#         -P run_conformance.cmake
#
# COMPARE_ARGS (a ;-list) is passed on to gl_compare: --tolerance 0 --min-percent 100 for the
# programs whose output is data compared byte for byte.
#
# With SHADELAB_EXE empty (libshadelab-gl not built yet) only Mesa's build runs and its image is
# checked not to be blank. With SELFCHECK=ON Mesa's softpipe driver is compared with llvmpipe
# (NAME.selfcheck-*.png). With VALUES=ON the program also writes NAME.mesa.txt and
# NAME.shadelab.txt (a value per line), compared one by one by VALUES_COMPARE (gl_values)
# within the relative tolerance VALUES_REL (0: equal).
file(MAKE_DIRECTORY ${OUT_DIR})

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NAME}: ${what} failed (exit status ${rc})")
  endif()
endfunction()

if(SELFCHECK)  # own file names: may run beside the conformance test of the same program
  set(llvm_png ${OUT_DIR}/${NAME}.selfcheck-llvmpipe.png)
  set(soft_png ${OUT_DIR}/${NAME}.selfcheck-softpipe.png)
  file(REMOVE ${llvm_png} ${soft_png})
  run_step("Mesa's build under llvmpipe"
           ${CMAKE_COMMAND} -E env GALLIUM_DRIVER=llvmpipe ${MESA_EXE} ${llvm_png})
  run_step("Mesa's build under softpipe"
           ${CMAKE_COMMAND} -E env GALLIUM_DRIVER=softpipe ${MESA_EXE} ${soft_png})
  # A disagreement is reported, not fatal: this measures Mesa.
  execute_process(COMMAND ${COMPARE} ${llvm_png} ${soft_png} --name ${NAME}.softpipe
                          --diff ${OUT_DIR}/${NAME}.selfcheck-diff.png)
  return()
endif()

set(mesa_png ${OUT_DIR}/${NAME}.mesa.png)
file(REMOVE ${mesa_png} ${OUT_DIR}/${NAME}.mesa.txt ${OUT_DIR}/${NAME}.shadelab.txt)
run_step("Mesa's build (${MESA_EXE})" ${MESA_EXE} ${mesa_png})



if(NOT SHADELAB_EXE)
  message(STATUS "${NAME}: libshadelab-gl is not built; checked Mesa's build only")
  run_step("not-blank check" ${COMPARE} --not-blank ${mesa_png})
  return()
endif()

set(shadelab_png ${OUT_DIR}/${NAME}.shadelab.png)
set(diff_png ${OUT_DIR}/${NAME}.diff.png)
file(REMOVE ${shadelab_png} ${diff_png})
run_step("shadelab-gl's build (${SHADELAB_EXE})" ${SHADELAB_EXE} ${shadelab_png})
if(VALUES)
  if(NOT VALUES_REL)
    set(VALUES_REL 0)
  endif()
  execute_process(COMMAND ${VALUES_COMPARE} ${OUT_DIR}/${NAME}.mesa.txt
                          ${OUT_DIR}/${NAME}.shadelab.txt --name ${NAME} --rel ${VALUES_REL}
                  RESULT_VARIABLE values_rc)
endif()
run_step("comparison with Mesa" ${COMPARE} ${mesa_png} ${shadelab_png} --name ${NAME}
         --diff ${diff_png} ${COMPARE_ARGS})
if(VALUES AND NOT values_rc EQUAL 0)
  message(FATAL_ERROR "${NAME}: the values differ from Mesa's (gl_values above)")
endif()
