cmake_minimum_required(VERSION 3.25)
# Follows docs/ARCHITECTURE.md's "Adding an effect" in a scratch copy of the tree: a toy effect
# (`toy_spring`, the gas spring under another name) is added by exactly the files the recipe
# names, and nothing else. Then:
#  - the files touched are counted against the recipe's own count (RECIPE_FILES);
#  - the effect-name budget holds with the toy at two files outside the registry (its header and
#    source);
#  - with BUILD=ON (the slow label), the scratch tree builds the model, config and allocation
#    tests, runs the list, documentation, toy and allocation tests, and then drops the toy from
#    one list to see the list test fail naming that file.
# Usage: cmake -DSOURCE_DIR=<repo> -DSCRATCH=<dir> -DRECIPE_FILES=<n> [-DBUILD=ON] -P add_toy_effect.cmake
foreach(required SOURCE_DIR SCRATCH RECIPE_FILES)
  if(NOT ${required})
    message(FATAL_ERROR "add_toy_effect: give -D${required}=...")
  endif()
endforeach()

set(tree "${SCRATCH}/tree")
file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${tree}")
file(GLOB top RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/*" "${SOURCE_DIR}/.*")
foreach(entry IN LISTS top)
  if(entry MATCHES "^(build|\\.git|out)$")
    continue()
  endif()
  file(COPY "${SOURCE_DIR}/${entry}" DESTINATION "${tree}")
endforeach()

set(touched "")
function(fail what)
  message(FATAL_ERROR "add_toy_effect: ${what}")
endfunction()
# A new file: FROM (relative) renamed gas_spring -> toy_spring, GasSpring -> ToySpring.
function(copy_renamed from to)
  file(READ "${tree}/${from}" text)
  string(REPLACE "gas_spring" "toy_spring" text "${text}")
  string(REPLACE "GasSpring" "ToySpring" text "${text}")
  file(WRITE "${tree}/${to}" "${text}")
  set(touched ${touched} "${to}" PARENT_SCOPE)
endfunction()
# An edit: the first occurrence of ANCHOR in FILE becomes REPLACEMENT.
function(edit file anchor replacement)
  file(READ "${tree}/${file}" text)
  string(FIND "${text}" "${anchor}" at)
  if(at EQUAL -1)
    fail("${file}: the recipe's anchor is gone: ${anchor}")
  endif()
  string(LENGTH "${anchor}" length)
  string(SUBSTRING "${text}" 0 ${at} head)
  math(EXPR rest_at "${at} + ${length}")
  string(SUBSTRING "${text}" ${rest_at} -1 tail)
  file(WRITE "${tree}/${file}" "${head}${replacement}${tail}")
  list(FIND touched "${file}" seen)
  if(seen EQUAL -1)
    set(touched ${touched} "${file}" PARENT_SCOPE)
  endif()
endfunction()
# An edit that repeats, after the block that names the gas spring, that block renamed, SEPARATOR
# between. The block runs from ANCHOR to the first END after it (END not included).
function(repeat_block file anchor end separator)
  file(READ "${tree}/${file}" text)
  string(FIND "${text}" "${anchor}" at)
  if(at EQUAL -1)
    fail("${file}: the recipe's anchor is gone: ${anchor}")
  endif()
  string(SUBSTRING "${text}" ${at} -1 from_anchor)
  string(FIND "${from_anchor}" "${end}" length)
  if(length EQUAL -1)
    fail("${file}: no end of the block after ${anchor}")
  endif()
  string(SUBSTRING "${from_anchor}" 0 ${length} block)
  string(REPLACE "gas_spring" "toy_spring" copy "${block}")
  edit("${file}" "${block}" "${block}${separator}${copy}")
  set(touched ${touched} PARENT_SCOPE)
endfunction()

# 1. The effect's header and source.
copy_renamed(model/effects/gas_spring.hpp model/effects/toy_spring.hpp)
copy_renamed(model/effects/gas_spring.cpp model/effects/toy_spring.cpp)
edit(model/CMakeLists.txt "  effects/gas_spring.cpp\n" "  effects/gas_spring.cpp\n  effects/toy_spring.cpp\n")
# 2. The registry.
edit(model/effects/effect_set.hpp "#include \"model/effects/gas_spring.hpp\"\n"
     "#include \"model/effects/gas_spring.hpp\"\n#include \"model/effects/toy_spring.hpp\"\n")
edit(model/effects/effect_set.hpp "GasSpringEffect, " "GasSpringEffect, ToySpringEffect, ")
# 3. Its tests.
copy_renamed(tests/model/effects/test_gas_spring.cpp tests/model/effects/test_toy_spring.cpp)
edit(tests/CMakeLists.txt "  model/effects/test_gas_spring.cpp\n"
     "  model/effects/test_gas_spring.cpp\n  model/effects/test_toy_spring.cpp\n")
# 4. The lists outside the registry.
foreach(toml etc/mrd/mrd.toml etc/mrd/plant.toml fuzz/corpus/config/mrd.toml)
  repeat_block(${toml} "[damper.effects.gas_spring]" "\n\n" "\n\n")
endforeach()
repeat_block(fuzz/dict/config.dict "\"[damper.effects.gas_spring]\"" "\n" "\n")
edit(docs/MODEL.md "### gas_spring (" "### toy_spring (`toy_spring.hpp`)\n\nThe gas spring under another name.\n\n### gas_spring (")
repeat_block(docs/FIRMWARE.md "| `damper.effects.gas_spring.enabled`" "\n| `damper.effects.learned_terms" "\n")
repeat_block(tests/generator/damper_truth.py "    if \"gas_spring\" in size:" "\n    F = F + 50.0" "\n")
foreach(study tools/residual/detection-study.sh tests/generator/independent-study.sh
              tests/generator/random-damper-study.sh)
  file(READ "${tree}/${study}" text)
  if(NOT text MATCHES "\neffects=[(]([^)]*)[)]")
    fail("${study}: no effects=(...) line")
  endif()
  set(line "effects=(${CMAKE_MATCH_1})")
  string(REPLACE " gas_spring " " gas_spring toy_spring " toy_line "${line}")
  edit(${study} "${line}" "${toy_line}")
endforeach()

list(LENGTH touched count)
list(JOIN touched "\n  " listing)
message(STATUS "the recipe touched ${count} files:\n  ${listing}")
if(NOT count EQUAL RECIPE_FILES)
  fail("the recipe touched ${count} files, docs/ARCHITECTURE.md says ${RECIPE_FILES}")
endif()

# The name budget: every effect within it, the toy at exactly two files outside the registry.
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${tree} -P ${tree}/cmake/check_effect_names.cmake
                RESULT_VARIABLE budget_failed OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(budget_failed)
  fail("the name budget fails with the toy:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${tree} -DMAX_FILES=1 -P ${tree}/cmake/check_effect_names.cmake
                OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT out MATCHES "toy_spring: 2 files")
  fail("the toy is not named in exactly two files outside the registry:\n${out}")
endif()
message(STATUS "the toy is named in 2 source files outside the registry; the budget holds")

if(NOT BUILD)
  return()
endif()

set(build "${SCRATCH}/build")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${tree} -B ${build} -G Ninja -DCMAKE_BUILD_TYPE=Release
                        -DCMAKE_UNITY_BUILD=OFF
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(failed)
  fail("configure failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${build}
                        --target mrd_model_tests mrd_config_tests mrd_effects_allocation_tests
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(failed)
  fail("the scratch build failed:\n${out}")
endif()
function(run_tests binary filter expect_pass)
  execute_process(COMMAND ${build}/tests/${binary} --gtest_filter=${filter}
                  RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(expect_pass AND failed)
    fail("${binary} ${filter} failed with the toy:\n${out}")
  endif()
  if(NOT expect_pass AND NOT failed)
    fail("${binary} ${filter} passed with the toy left out of a list")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
run_tests(mrd_model_tests "ToySpring*:GasSpring*" ON)
if(NOT last_output MATCHES "OK \\] ToySpring[.]")
  fail("the toy's tests did not run:\n${last_output}")
endif()
run_tests(mrd_config_tests "EffectLists.*:ConfigDefault.*:EffectsConfig.*" ON)
# They switch on every effect of AllEffects (RealTimeEffects.EveryEffectOfTheListIsOnInTheseTests).
run_tests(mrd_effects_allocation_tests "*" ON)
message(STATUS "the scratch build with the toy passes its list, documentation, toy and allocation tests")

# Left out of one list, the list test names the file.
file(READ "${tree}/etc/mrd/plant.toml" plant)
string(REPLACE "[damper.effects.toy_spring]" "[damper.effects.toy_spring_gone]" plant "${plant}")
file(WRITE "${tree}/etc/mrd/plant.toml" "${plant}")
run_tests(mrd_config_tests "EffectLists.*" OFF)
if(NOT last_output MATCHES "toy_spring: not in etc/mrd/plant.toml")
  fail("the list test failed without naming the file:\n${last_output}")
endif()
message(STATUS "left out of etc/mrd/plant.toml, the toy fails EffectLists, naming the file")
