#include "WriteWarnings.h"
#include <QMessageBox>

namespace stepdeck::ui {

namespace {
QString trParam(const QString& text)
{
    return QCoreApplication::translate("Parameters", text.toUtf8().constData());
}
} // namespace

QStringList WriteWarnings::collect(const ParameterSchema& schema, const ParameterSet& set)
{
    QStringList warnings;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = schema.find(it.key());
        if (spec && !spec->warning.isEmpty())
            warnings << QStringLiteral("<b>%1</b>: %2")
                            .arg(trParam(spec->label).toHtmlEscaped(),
                                 trParam(spec->warning).toHtmlEscaped());
    }
    return warnings;
}

bool WriteWarnings::confirm(QWidget* parent, const ParameterSchema& schema, const ParameterSet& set)
{
    const QStringList warnings = collect(schema, set);
    if (warnings.isEmpty())
        return true;
    const auto answer = QMessageBox::warning(
        parent, tr("Write parameters"),
        tr("Please read before writing:<br><br>%1").arg(warnings.join(QStringLiteral("<br>"))),
        QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel);
    return answer == QMessageBox::Ok;
}

} // namespace stepdeck::ui
