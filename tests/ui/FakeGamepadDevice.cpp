// FakeGamepadDevice's moc output, built once for every widget test (tests/CMakeLists.txt).
#include "FakeGamepadDevice.h"
