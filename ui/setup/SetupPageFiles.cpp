// SetupPage: saving and loading parameter files (the CLI's JSON format).
#include "SetupPage.h"
#include "common/Dialogs.h"
#include "machine/MachineContext.h"
#include "model/ParameterFile.h"
#include "setup/DiffDialog.h"
#include <QFileInfo>

namespace stepdeck::ui {

bool SetupPage::saveToFile(const QString& path, QString* error) const
{
    ParameterSet set;
    QStringList errors;
    if (!formValues(&set, &errors)) {
        *error = tr("Not saved: %1").arg(errors.join(QStringLiteral("; ")));
        return false;
    }
    return ParameterFile::save(m_schema, m_context->modelId(), set, path, error) ==
           ParameterFile::Status::Ok;
}

bool SetupPage::readFile(const QString& path, ParameterSet* set, QString* error) const
{
    return ParameterFile::load(m_schema, m_context->modelId(), m_context->axes(), path, set,
                               error) == ParameterFile::Status::Ok;
}

void SetupPage::saveAs()
{
    if (!hasSettableParameters())
        return; // the page says why (File menu: the same words in the status bar)
    dialogs::saveFile(this, QStringLiteral("parameters"), tr("Save parameters"),
                      m_context->modelId() + QStringLiteral("-parameters.json"),
                      tr("Parameter files (*.json)"), [this](const QString& path) {
                          QString error;
                          if (saveToFile(path, &error))
                              setMessage(tr("Saved to %1.").arg(path), false);
                          else
                              setMessage(error, true);
                      });
}

void SetupPage::load()
{
    if (!hasSettableParameters())
        return;
    dialogs::openFile(this, QStringLiteral("parameters"), tr("Load parameters"),
                      tr("Parameter files (*.json)"),
                      [this](const QString& path) { loadFile(path); });
}

DiffDialog* SetupPage::loadFile(const QString& path)
{
    ParameterSet loaded;
    QString error;
    if (!readFile(path, &loaded, &error)) {
        setMessage(error, true);
        return nullptr;
    }
    ParameterSet current;
    formValues(&current, nullptr);
    const QString name = QFileInfo(path).fileName();
    auto* dialog =
        new DiffDialog(DiffDialog::compare(m_schema, current, loaded,
                                           m_context->session()->spec().options.axisNames),
                       name, window());
    connect(dialog, &QDialog::finished, this, [this, loaded, name](int choice) {
        if (choice == DiffDialog::Cancel)
            return;
        applyToForm(loaded);
        setMessage(tr("Loaded %1 into the form.").arg(name), false);
        if (choice == DiffDialog::LoadAndWrite)
            writeSet(loaded, false, true); // the whole file, not only what differs
    });
    dialogs::showForPart(dialog, this);
    return dialog;
}

} // namespace stepdeck::ui
