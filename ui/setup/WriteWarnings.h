#pragma once
#include "model/ParameterSchema.h"
#include <QCoreApplication>

class QWidget;

namespace stepdeck::ui {

// The schema's warnings (e.g. "communication continues at the new address") are said before
// anything is sent: true when there are none or the technician confirmed them.
class WriteWarnings
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::WriteWarnings)
public:
    static QStringList collect(const ParameterSchema& schema, const ParameterSet& set);
    static bool confirm(QWidget* parent, const ParameterSchema& schema, const ParameterSet& set);
};

} // namespace stepdeck::ui
