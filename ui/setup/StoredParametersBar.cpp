#include "StoredParametersBar.h"
#include "common/Dialogs.h"
#include "machine/MachineContext.h"
#include "model/ModelOperations.h"
#include "setup/SetupPage.h"
#include "setup/WriteWarnings.h"
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

namespace stepdeck::ui {

namespace {

QStringList labels(const ParameterSchema& schema, const QStringList& names)
{
    QStringList out;
    for (const QString& name : names) {
        const ParameterSpec* spec = schema.find(name);
        out << (spec ? ParameterSchema::displayText(spec->label) : name);
    }
    return out;
}
} // namespace

StoredParametersBar::StoredParametersBar(MachineContext* context, SetupPage* page, QWidget* parent)
    : QWidget(parent), m_context(context), m_page(page),
      m_store(new QPushButton(tr("Store as power-on values\u2026"), this)),
      m_read(new QPushButton(tr("Read stored values"), this)), m_message(new QLabel(this))
{
    setObjectName(QStringLiteral("storedParametersBar"));
    m_store->setToolTip(tr("Write the form's values into the controller's own memory: it "
                           "starts with them after every power-on"));
    m_read->setToolTip(tr("Read the values stored in the controller into the form"));
    m_message->setWordWrap(true);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_store);
    layout->addWidget(m_read);
    layout->addWidget(m_message, 1);
    connect(m_store, &QPushButton::clicked, this, [this] { store(true); });
    connect(m_read, &QPushButton::clicked, this, &StoredParametersBar::readStored);
    connect(context, &MachineContext::modelChanged, this, &StoredParametersBar::refresh);
    connect(context->session(), &ControllerSession::linkStateChanged, this,
            &StoredParametersBar::refresh);
    connect(context->session(), &ControllerSession::requestFinished, this,
            &StoredParametersBar::onResult);
    refresh();
}

QString StoredParametersBar::messageText() const
{
    return m_message->text();
}

void StoredParametersBar::refresh()
{
    setVisible(m_context->capabilities().storedParameters);
    const bool connected = m_context->isConnected();
    m_store->setEnabled(connected);
    m_read->setEnabled(connected);
}

bool StoredParametersBar::store(bool ask)
{
    ParameterSet set;
    QStringList errors;
    if (!m_page->formValues(&set, &errors)) {
        setMessage(tr("Invalid values cannot be stored: %1").arg(errors.join(QStringLiteral("; "))),
                   true);
        return false;
    }
    if (ask) {
        // Non-modal (issue 7 rule 5): STOP and PANIC stay usable while the question is open.
        const ParameterSchema schema = m_context->schema();
        const QStringList warnings = WriteWarnings::collect(schema, set);
        dialogs::message(
            this, QMessageBox::Question, tr("Store power-on values"),
            tr("Store the form's values in the controller? It starts with them after every "
               "power-on. Values without a stored form are left out.%1")
                .arg(warnings.isEmpty()
                         ? QString()
                         : QStringLiteral("<br><br>") + warnings.join(QStringLiteral("<br>"))),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::No,
            [this, set](QMessageBox::StandardButton answer) {
                if (answer == QMessageBox::Yes)
                    sendStore(set);
                else
                    setMessage(tr("Not stored: cancelled."), false);
            });
        return true;
    }
    sendStore(set);
    return true;
}

void StoredParametersBar::sendStore(const ParameterSet& set)
{
    if (!m_context->isConnected()) {
        setMessage(tr("Not stored: not connected."), true);
        return;
    }
    m_pendingStore = m_context->session()->modelOperation(
        operation::kStoreParameters, {{operation::arg::kParameters, QVariant::fromValue(set)},
                                      {operation::arg::kSkipUnstorable, true}});
    setMessage(tr("Storing\u2026"), false);
}

void StoredParametersBar::readStored()
{
    m_pendingRead = m_context->session()->modelOperation(operation::kReadStoredParameters);
    setMessage(tr("Reading the stored values\u2026"), false);
}

void StoredParametersBar::onResult(const CommandResult& result)
{
    const ParameterSchema schema = m_context->schema();
    if (result.id == m_pendingStore && m_pendingStore) {
        m_pendingStore = 0;
        if (!result.ok())
            return setMessage(tr("Not stored: %1").arg(result.message), true);
        QStringList skipped;
        for (const QVariant& v : result.value.toMap().value(QStringLiteral("skipped")).toList())
            skipped << v.toString();
        setMessage(skipped.isEmpty()
                       ? tr("Stored as power-on values.")
                       : tr("Stored as power-on values; not stored (no stored form): %1.")
                             .arg(labels(schema, skipped).join(QStringLiteral(", "))),
                   false);
    } else if (result.id == m_pendingRead && m_pendingRead) {
        m_pendingRead = 0;
        if (!result.ok())
            return setMessage(tr("Reading the stored values failed: %1").arg(result.message), true);
        const QVariantMap map = result.value.toMap();
        const ParameterSet stored = map.value(QStringLiteral("parameters")).value<ParameterSet>();
        m_page->applyToForm(stored);
        QStringList notes;
        for (const QVariant& v : map.value(QStringLiteral("notes")).toList())
            notes << v.toString();
        setMessage(stored.isEmpty()
                       ? tr("Nothing is stored: the controller starts with its defaults.")
                       : tr("Stored values in the form: %1.%2")
                             .arg(labels(schema, stored.keys()).join(QStringLiteral(", ")),
                                  notes.isEmpty()
                                      ? QString()
                                      : QLatin1Char(' ') + notes.join(QLatin1Char(' '))),
                   false);
    }
}

void StoredParametersBar::setMessage(const QString& text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("QLabel { color: #c62828; }") : QString());
}

} // namespace stepdeck::ui
