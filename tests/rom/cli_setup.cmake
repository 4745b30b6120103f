# Copies the example and bad scenes and writes the closed-form tables they use.
file(REMOVE_RECURSE ${DST})
file(MAKE_DIRECTORY ${DST})
file(GLOB _tomls ${SRC}/*.toml ${CMAKE_CURRENT_LIST_DIR}/bad_scenes/*.toml)
file(COPY ${_tomls} DESTINATION ${DST})
foreach(spec "spheroid;1;0.6;spheroid_oblate.h5" "spheroid;1;2;spheroid_prolate.h5" "sphere;1;sphere.h5"
             "spheroid;1;1.8;spheroid_long.h5"
             # a family of tables for `sweep --param body[1].cavity.table=family_c%.1f.h5`
             "spheroid;1;0.5;family_c0.5.h5" "spheroid;1;2;family_c2.0.h5" "spheroid;1;3.5;family_c3.5.h5")
  execute_process(COMMAND ${TOOL} ${spec} WORKING_DIRECTORY ${DST} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "rom-closed-form-table ${spec} failed")
  endif()
endforeach()
file(WRITE ${DST}/not_a_table.h5 "this is not HDF5\n")
