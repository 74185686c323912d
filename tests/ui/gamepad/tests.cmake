# The SDL gamepad backend's polling (issue 21, idle cost); only in builds with SDL2.
if(TARGET SDL2::SDL2)
  stepdeck_add_test(tst_sdlgamepaddevice SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_sdlgamepaddevice.cpp
                    LABELS ui LIBS stepdeck_ui)
  stepdeck_test_definitions(tst_sdlgamepaddevice STEPDECK_HAVE_SDL2)
endif()
