# The motion layer (issue 30): canonical moves, their bounded queue, and contours laid on ticks
# as step streams.
stepdeck_add_test(tst_canonicalmove SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_canonicalmove.cpp LABELS unit)
stepdeck_add_test(tst_contoursteps SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_contoursteps.cpp LABELS unit)
stepdeck_add_test(tst_contourfeed SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_contourfeed.cpp LABELS unit)
# The switch executor (issue 49): spindle, coolant and outputs as the machine takes them, and
# the check naming every refusal of the run.
stepdeck_add_test(tst_switchexecutor SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_switchexecutor.cpp
                  ${CMAKE_SOURCE_DIR}/tests/core/program/ProgramCheckTestSupport.h LABELS unit)
# The stream executor (issue 49): a machine's step streams and their tick rates.
stepdeck_add_test(tst_streamexecutor SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_streamexecutor.cpp
                  ${CMAKE_SOURCE_DIR}/tests/core/program/ElabBoardTestSupport.h
                  ${CMAKE_SOURCE_DIR}/tests/core/program/ProgramCheckTestSupport.h LABELS unit)
# A move's rates (issue 49, issue 50): the feed-rate writes the check judges and the run sends.
stepdeck_add_test(tst_moverates SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_moverates.cpp
                  ${CMAKE_SOURCE_DIR}/tests/core/program/ElabBoardTestSupport.h LABELS unit)
