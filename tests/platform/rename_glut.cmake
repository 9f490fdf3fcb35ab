# Copies a static library with every glut* function it defines renamed shadelab_glut*, so that a
# program can link it beside freeglut's libglut (glut_shapes_vs_freeglut). Every defined glut*
# symbol is renamed, not a fixed list: one left behind would silently stand in for freeglut's.
#   cmake -DNM=nm -DOBJCOPY=objcopy -DIN=libshadelab-glut.a -DOUT=renamed.a -P rename_glut.cmake
execute_process(COMMAND ${NM} --defined-only --extern-only --format=posix ${IN}
                OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "rename_glut: ${NM} failed on ${IN}")
endif()
string(REPLACE "\n" ";" lines "${symbols}")
set(args)
foreach(line IN LISTS lines)
  if(line MATCHES "^(glut[A-Za-z0-9_]*) ")
    list(APPEND args --redefine-sym ${CMAKE_MATCH_1}=shadelab_${CMAKE_MATCH_1})
  endif()
endforeach()
if(NOT args)
  message(FATAL_ERROR "rename_glut: ${IN} defines no glut* symbol")
endif()
execute_process(COMMAND ${OBJCOPY} ${args} ${IN} ${OUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "rename_glut: ${OBJCOPY} failed")
endif()
