# CTest script: `cmake --install BUILD_DIR --prefix P` into a fresh folder outside the checkout,
# then P/bin/skein run from another folder finds the generic profile in P/share/skein and a
# user's own profile in $XDG_DATA_HOME/skein/machine_profiles, with no checkout in sight.
# Run as: cmake -DBUILD_DIR=... -DSOURCE_DIR=... -P install_test.cmake

set(temp "$ENV{TMPDIR}")
if(NOT temp)
  set(temp /tmp)
endif()
string(RANDOM LENGTH 8 tag)
set(work "${temp}/skein-install-test-${tag}")
set(prefix "${work}/prefix")
set(elsewhere "${work}/elsewhere")
set(user_data "${work}/user-data")
file(MAKE_DIRECTORY "${elsewhere}" "${user_data}/skein/machine_profiles")

function(fail message)
  file(REMOVE_RECURSE "${work}")
  message(FATAL_ERROR "${message}")
endfunction()

execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}"
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  fail("cmake --install failed (${code}): ${err}")
endif()
foreach(installed bin/skein share/skein/machine_profiles/generic.yaml
                  share/skein/machine_profiles/swg091n2.yaml share/doc/skein/README.md
                  share/doc/skein/docs/formats.md)
  if(NOT EXISTS "${prefix}/${installed}")
    fail("not installed: ${installed}")
  endif()
endforeach()

# skein run with HOME and XDG_DATA_HOME pointing at a folder of ours.
function(run_installed expected_code expected_out)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env "HOME=${work}" "XDG_DATA_HOME=${user_data}"
            "${prefix}/bin/skein" ${ARGN}
    WORKING_DIRECTORY "${elsewhere}" RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL expected_code OR NOT out MATCHES "${expected_out}")
    fail("skein ${ARGN}: exit ${code}, expected ${expected_code} and '${expected_out}'\n${out}${err}")
  endif()
endfunction()

run_installed(0 "proven against"
              compile "${SOURCE_DIR}/samples/hat/hat.obj" -t knitout -m generic -o out.k --verify)
if(NOT EXISTS "${elsewhere}/out.k")
  fail("out.k was not written in the working folder")
endif()
file(READ "${prefix}/share/skein/machine_profiles/generic.yaml" generic)
string(REPLACE "name: generic" "name: mine" mine "${generic}")
file(WRITE "${user_data}/skein/machine_profiles/mine.yaml" "${mine}")
run_installed(0 "valid on mine"
              verify out.k -m mine --against "${SOURCE_DIR}/samples/hat/hat.obj")
file(REMOVE_RECURSE "${work}")
