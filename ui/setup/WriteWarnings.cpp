#include "WriteWarnings.h"
#include "common/Dialogs.h"

namespace stepdeck::ui {

QStringList WriteWarnings::collect(const ParameterSchema& schema, const ParameterSet& set)
{
    QStringList warnings;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = schema.find(it.key());
        if (spec && !spec->warning.isEmpty())
            warnings << QStringLiteral("<b>%1</b>: %2")
                            .arg(ParameterSchema::displayText(spec->label).toHtmlEscaped(),
                                 ParameterSchema::displayText(spec->warning).toHtmlEscaped());
    }
    return warnings;
}

void WriteWarnings::confirm(QWidget* part, const ParameterSchema& schema, const ParameterSet& set,
                            std::function<void(bool)> done)
{
    const QStringList warnings = collect(schema, set);
    if (warnings.isEmpty()) {
        done(true);
        return;
    }
    QMessageBox* box = dialogs::message(
        part, QMessageBox::Warning, tr("Write parameters"),
        tr("Please read before writing:<br><br>%1").arg(warnings.join(QStringLiteral("<br>"))),
        QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel,
        [done](QMessageBox::StandardButton answer) { done(answer == QMessageBox::Ok); });
    box->setObjectName(QStringLiteral("writeWarnings"));
}

} // namespace stepdeck::ui
