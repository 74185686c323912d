#pragma once
// PreviewViewKind as test data (QFETCH) in the preview's tests: declared in one place, since a
// test batch may compile several of them as one (tests/CMakeLists.txt).
#include "program/PreviewProjection.h"
#include <QMetaType>

Q_DECLARE_METATYPE(stepdeck::ui::PreviewViewKind)
