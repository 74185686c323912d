#pragma once
#include "model/ParameterSchema.h"
#include <QCoreApplication>
#include <functional>

class QWidget;

namespace stepdeck::ui {

// The schema's warnings (e.g. "communication continues at the new address") are said before
// anything is sent. confirm() calls done(true) at once when there are none; otherwise it asks
// in a non-modal message box (part is disabled meanwhile) and calls done with the answer.
class WriteWarnings
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::WriteWarnings)
public:
    static QStringList collect(const ParameterSchema& schema, const ParameterSet& set);
    static void confirm(QWidget* part, const ParameterSchema& schema, const ParameterSet& set,
                        std::function<void(bool)> done);
};

} // namespace stepdeck::ui
