stepdeck_add_test(tst_laserbridgeconfig SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laserbridgeconfig.cpp LABELS unit)
stepdeck_add_test(tst_laserbridge_e2e SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laserbridge_e2e.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/LaserBridgeRig.h LABELS integration TIMEOUT 300)
stepdeck_add_test(tst_laserbridge_models SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laserbridge_models.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/LaserBridgeRig.h LABELS integration TIMEOUT 120)
stepdeck_add_test(tst_laserbridge_failures SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laserbridge_failures.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/LaserBridgeRig.h LABELS integration TIMEOUT 120)
stepdeck_add_test(tst_laseranswerpolicy SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laseranswerpolicy.cpp LABELS unit)
