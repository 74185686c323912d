#include "InputProgramsPage.h"
#include "common/ElidedLabel.h"
#include "machine/MachineContext.h"
#include "model/ModelOperations.h"
#include <QDateTime>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>

namespace stepdeck::ui {

namespace {
constexpr int kTitleMax = 60; // what the controller takes as a header (EMIS: printable ASCII)

// The model's plain words for input `n` (the raw word "inputs"), e.g. "Input 1: reference
// switch of axis X (or a free input when no switch is wired)."
QString inputDescription(const ModelInfo* model, int n)
{
    if (!model || !model->presentation.statusWords)
        return {};
    for (const StatusWordInfo& word : model->presentation.statusWords({})) {
        if (word.key != QLatin1String("inputs"))
            continue;
        for (const StatusBitInfo& bit : word.bits) {
            if (bit.bit == n - 1)
                return bit.description;
        }
    }
    return {};
}
} // namespace

InputProgramsPage::InputProgramsPage(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_list(new QListWidget(this)),
      m_title(new QLineEdit(this)), m_commands(new QPlainTextEdit(this)),
      m_check(new ElidedLabel(this, 2)), m_write(new QPushButton(tr("Write to controller"), this)),
      m_force(new QPushButton(tr("Write anyway"), this)),
      m_erase(new QPushButton(tr("Erase from controller"), this)),
      m_message(new ElidedLabel(this, 2))
{
    m_title->setMaxLength(kTitleMax);
    m_title->setPlaceholderText(tr("e.g. Input 8: vector move X"));
    m_commands->setPlaceholderText(tr("One command per line, e.g.\n$H,x\nL1,x191\nW1500"));
    m_commands->setTabChangesFocus(true);
    // Two lines reserved each, longer texts elided (the full text in the tooltip): the check
    // that follows the typing never moves the editor or the buttons (issue 16).
    for (ElidedLabel* label : {m_check, m_message})
        label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_force->setVisible(false);
    m_force->setToolTip(tr("The input carries a reference switch: write only if no switch is "
                           "wired to it"));
    m_list->setMaximumWidth(260);
    auto* form = new QFormLayout;
    form->addRow(tr("Title:"), m_title);
    form->addRow(tr("Commands:"), m_commands);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_write);
    buttons->addWidget(m_force);
    buttons->addWidget(m_erase);
    buttons->addStretch(1);
    auto* right = new QVBoxLayout;
    right->addLayout(form, 1);
    right->addWidget(m_check);
    right->addLayout(buttons);
    right->addWidget(m_message);
    auto* note = new QLabel(tr("The controller cannot read its programs back: the list shows what "
                               "was written or erased from here."),
                            this);
    note->setWordWrap(true);
    auto* left = new QVBoxLayout;
    left->addWidget(m_list, 1);
    left->addWidget(note);
    auto* layout = new QHBoxLayout(this);
    layout->addLayout(left);
    layout->addLayout(right, 1);

    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0)
            loadDraft(row + 1);
    });
    connect(m_title, &QLineEdit::textEdited, this, [this] { saveDraft(); });
    connect(m_commands, &QPlainTextEdit::textChanged, this, [this] { saveDraft(); });
    connect(m_write, &QPushButton::clicked, this, [this] { writeProgram(false); });
    connect(m_force, &QPushButton::clicked, this, [this] { writeProgram(true); });
    connect(m_erase, &QPushButton::clicked, this, &InputProgramsPage::eraseProgram);
    connect(context, &MachineContext::modelChanged, this, &InputProgramsPage::rebuild);
    connect(context->session(), &ControllerSession::linkStateChanged, this,
            &InputProgramsPage::refresh);
    connect(context->session(), &ControllerSession::requestFinished, this,
            &InputProgramsPage::onResult);
    rebuild();
}

QString InputProgramsPage::settingsKey(int input) const
{
    return QStringLiteral("inputPrograms/%1/%2/").arg(m_context->modelId()).arg(input);
}

int InputProgramsPage::currentInput() const
{
    return m_list->currentRow() + 1;
}

QString InputProgramsPage::messageText() const
{
    return m_message->text();
}

QString InputProgramsPage::checkText() const
{
    return m_check->text();
}

void InputProgramsPage::rebuild()
{
    m_list->clear();
    const int inputs =
        m_context->capabilities().inputPrograms ? m_context->capabilities().digitalInputs : 0;
    for (int n = 1; n <= inputs; ++n) {
        m_list->addItem(QString());
        updateItem(n);
    }
    if (inputs > 0)
        m_list->setCurrentRow(0);
    refresh();
}

void InputProgramsPage::updateItem(int input)
{
    QListWidgetItem* item = m_list->item(input - 1);
    if (!item)
        return;
    const QSettings settings;
    const QString key = settingsKey(input);
    const QString state = settings.value(key + QStringLiteral("state")).toString();
    const QString when = settings.value(key + QStringLiteral("when")).toString();
    QString stateText = tr("not written from here");
    if (state == QLatin1String("written"))
        stateText = tr("written %1").arg(when);
    else if (state == QLatin1String("erased"))
        stateText = tr("erased %1").arg(when);
    const QString title = settings.value(key + QStringLiteral("title")).toString();
    item->setText(tr("Input %1: %2\n%3")
                      .arg(input)
                      .arg(title.isEmpty() ? tr("(no title)") : title, stateText));
    item->setToolTip(inputDescription(m_context->model(), input));
}

void InputProgramsPage::selectInput(int input)
{
    m_list->setCurrentRow(input - 1);
}

void InputProgramsPage::loadDraft(int input)
{
    const QSettings settings;
    m_loading = true;
    m_title->setText(settings.value(settingsKey(input) + QStringLiteral("title")).toString());
    m_commands->setPlainText(settings.value(settingsKey(input) + QStringLiteral("commands"))
                                 .toStringList()
                                 .join(QLatin1Char('\n')));
    m_loading = false;
    m_force->setVisible(false);
    setMessage(inputDescription(m_context->model(), input), false);
    refresh();
}

void InputProgramsPage::saveDraft()
{
    if (m_loading || currentInput() < 1)
        return;
    QSettings settings;
    settings.setValue(settingsKey(currentInput()) + QStringLiteral("title"), m_title->text());
    settings.setValue(settingsKey(currentInput()) + QStringLiteral("commands"), commandLines());
    m_force->setVisible(false);
    updateItem(currentInput());
    refresh();
}

QStringList InputProgramsPage::commandLines() const
{
    QStringList lines;
    for (const QString& line : m_commands->toPlainText().split(QLatin1Char('\n'))) {
        if (!line.trimmed().isEmpty())
            lines << line.trimmed();
    }
    return lines;
}

QStringList InputProgramsPage::problems() const
{
    QStringList out;
    for (QChar c : m_title->text()) {
        if (c.unicode() < 0x20 || c.unicode() >= 0x7F) {
            out << tr("Title: printable ASCII only (no umlauts)");
            break;
        }
    }
    const ModelInfo* model = m_context->model();
    const QStringList lines = commandLines();
    if (lines.isEmpty())
        out << tr("A program needs at least one command.");
    for (int i = 0; i < lines.size(); ++i) {
        const QString why = model && model->presentation.checkProgramCommand
                                ? model->presentation.checkProgramCommand(lines[i])
                                : QString();
        if (!why.isEmpty())
            out << tr("Line %1: %2").arg(i + 1).arg(why);
    }
    return out;
}

void InputProgramsPage::refresh()
{
    const QStringList issues = problems();
    m_check->setText(issues.isEmpty() ? tr("Every command is valid.")
                                      : issues.join(QLatin1Char('\n')));
    m_check->setStyleSheet(issues.isEmpty() ? QStringLiteral("QLabel { color: #2e7d32; }")
                                            : QStringLiteral("QLabel { color: #c62828; }"));
    const bool ready = m_context->isConnected() && currentInput() >= 1 && m_pending == 0;
    m_write->setEnabled(ready && issues.isEmpty());
    m_force->setEnabled(ready && issues.isEmpty());
    m_erase->setEnabled(ready);
}

bool InputProgramsPage::writeProgram(bool force)
{
    const int input = currentInput();
    if (input < 1 || !problems().isEmpty() || !m_context->isConnected() || m_pending)
        return false;
    m_pendingInput = input;
    m_pendingErase = false;
    m_pending = m_context->session()->modelOperation(operation::kWriteInputProgram,
                                                     {{operation::arg::kInput, input},
                                                      {operation::arg::kTitle, m_title->text()},
                                                      {operation::arg::kCommands, commandLines()},
                                                      {operation::arg::kForce, force}});
    setMessage(tr("Writing the program of input %1\u2026").arg(input), false);
    refresh();
    return true;
}

void InputProgramsPage::eraseProgram()
{
    const int input = currentInput();
    if (input < 1 || !m_context->isConnected() || m_pending)
        return;
    m_pendingInput = input;
    m_pendingErase = true;
    m_pending = m_context->session()->modelOperation(operation::kEraseInputProgram,
                                                     {{operation::arg::kInput, input}});
    setMessage(tr("Erasing the program of input %1\u2026").arg(input), false);
    refresh();
}

void InputProgramsPage::onResult(const CommandResult& result)
{
    if (result.id != m_pending || m_pending == 0)
        return;
    m_pending = 0;
    const int input = m_pendingInput;
    if (result.ok()) {
        QSettings settings;
        settings.setValue(settingsKey(input) + QStringLiteral("state"),
                          m_pendingErase ? QStringLiteral("erased") : QStringLiteral("written"));
        settings.setValue(
            settingsKey(input) + QStringLiteral("when"),
            QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")));
        updateItem(input);
        setMessage(m_pendingErase
                       ? tr("The program of input %1 is erased.").arg(input)
                       : tr("The program of input %1 is stored in the controller.").arg(input),
                   false);
    } else {
        // A refusal for an input with a reference function can be overridden on purpose.
        m_force->setVisible(result.error == ErrorKind::Refused && !m_pendingErase);
        setMessage(result.message, true);
    }
    refresh();
}

void InputProgramsPage::setMessage(const QString& text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("QLabel { color: #c62828; }") : QString());
}

} // namespace stepdeck::ui
