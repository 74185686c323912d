#pragma once
#include <QCoreApplication>
#include <QString>

namespace stepdeck::ui {

// How the Program page writes its estimated times (issue 20): always marked as estimates,
// since the preview knows no accelerations and only the rates the models' data gives.
class ProgramTimes
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::ProgramTimes)
public:
    static QString duration(double seconds);          // "1 min 20 s"
    static QString estimatedDuration(double seconds); // "≈ 1 min 20 s (estimated)"
    static QString estimatedLeft(double seconds);     // "≈ 1 min 20 s left (estimated)"
};

} // namespace stepdeck::ui
