#pragma once
// NumberError as test data (QFETCH) in tst_numberparsing and tst_parameterschema: declared in
// one place, since a test batch may compile both files as one (tests/CMakeLists.txt).
#include "model/NumberParsing.h"
#include <QMetaType>

Q_DECLARE_METATYPE(stepdeck::NumberError)
