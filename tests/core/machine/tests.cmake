# Machine descriptions: the "stepdeck-machine" file, its validation and unit conversion.
stepdeck_add_test(tst_machinefile SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinefile.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MachineFileTestSupport.h LABELS unit)
stepdeck_add_test(tst_machinefileformat SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinefileformat.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MachineFileTestSupport.h LABELS unit)
stepdeck_test_definitions(tst_machinefile STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# A machine of an E-LAB and a Nanotec simulator on two pseudo-terminals.
stepdeck_add_test(tst_machine SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machine.cpp
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h LABELS integration)
# A machine axis' jogAcceleration, its default and the controller's ramp (issue 28 item 6).
stepdeck_add_test(tst_jogacceleration SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_jogacceleration.cpp LABELS unit)
# Issue 28 item 6: a release from full jog speed stands within the stopping distance, at the
# E-LAB simulator on a pseudo-terminal.
stepdeck_add_test(tst_machinejogstop SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinejogstop.cpp
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h LABELS integration)
# Issue 28 item 4: STOP mid-move on every model, then an absolute move without referencing
# again, at the simulators on pseudo-terminals.
stepdeck_add_test(tst_machinestop SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinestop.cpp
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h LABELS integration)
# Who moves the machine (issue 49 item 4): one holder of its motion at a time (pure).
stepdeck_add_test(tst_motionownership SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_motionownership.cpp
                  LABELS unit)
