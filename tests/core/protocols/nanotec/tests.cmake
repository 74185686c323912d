stepdeck_add_test(tst_nanoteccodec SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanoteccodec.cpp LABELS unit)
stepdeck_add_test(tst_nanotecsimulator SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecsimulator.cpp LABELS unit)
stepdeck_add_test(tst_nanotecdriveclosedloop SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecdriveclosedloop.cpp LABELS unit)
stepdeck_add_test(tst_nanoteccontroller SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanoteccontroller.cpp ${CMAKE_CURRENT_LIST_DIR}/NanotecRig.h LABELS unit)
stepdeck_add_test(tst_nanotecparameterio SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecparameterio.cpp ${CMAKE_CURRENT_LIST_DIR}/NanotecRig.h LABELS unit)
stepdeck_add_test(tst_nanotec_e2e SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotec_e2e.cpp
                  LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_nanotec_e2e stepdeck-cli stepdeck-sim)
stepdeck_add_test(tst_nanotecclosedloop SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecclosedloop.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/NanotecRig.h LABELS unit)
stepdeck_add_test(tst_nanotecsafety SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecsafety.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/NanotecRig.h LABELS unit)
stepdeck_add_test(tst_nanotecpositionerror SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecpositionerror.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/NanotecRig.h LABELS unit)
stepdeck_add_test(tst_nanotecheldsettings SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecheldsettings.cpp LABELS unit)
stepdeck_add_test(tst_nanotecpollplan SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecpollplan.cpp LABELS unit)
