#include "MachineFileActions.h"
#include "MachineContext.h"
#include "MachineEditor.h"
#include "RecentMachines.h"
#include "common/Dialogs.h"
#include "connection/ConnectionSettings.h"
#include "machine/Machine.h"
#include "machine/MachineFile.h"
#include "machine/ToolTableDialog.h"
#include <QAction>
#include <QFileInfo>
#include <QMenu>

namespace stepdeck::ui {

MachineFileActions::MachineFileActions(MachineContext* context, QWidget* window)
    : QObject(window), m_context(context), m_window(window),
      m_new(new QAction(tr("&New machine\u2026"), this)),
      m_open(new QAction(tr("&Open machine\u2026"), this)),
      m_edit(new QAction(tr("&Edit machine\u2026"), this)),
      m_tools(new QAction(tr("&Tool table\u2026"), this)),
      m_recent(new QMenu(tr("&Recent machines"), window))
{
    setObjectName(QStringLiteral("machineFileActions"));
    m_recent->setObjectName(QStringLiteral("recentMachinesMenu"));
    m_edit->setToolTip(tr("Edit the machine open now, or choose a machine file to edit"));
    connect(m_new, &QAction::triggered, this, &MachineFileActions::newMachine);
    connect(m_open, &QAction::triggered, this, &MachineFileActions::chooseMachineToOpen);
    connect(m_edit, &QAction::triggered, this, &MachineFileActions::editMachine);
    m_tools->setToolTip(tr("The machine's tools: the lengths G43 applies, the texts M6 shows"));
    // Not modal (tst_dialogpolicy): the window keeps its STOP while the table is edited.
    connect(m_tools, &QAction::triggered, this, [this] {
        if (!m_toolDialog) {
            m_toolDialog = new ToolTableDialog(m_context->tools(), m_window);
            m_toolDialog->setAttribute(Qt::WA_DeleteOnClose);
        }
        m_toolDialog->show();
        m_toolDialog->raise();
        m_toolDialog->activateWindow();
    });
    connect(m_recent, &QMenu::aboutToShow, this, &MachineFileActions::rebuildRecentMenu);
    rebuildRecentMenu();
}

void MachineFileActions::addTo(QMenu* menu)
{
    menu->addAction(m_new);
    menu->addAction(m_open);
    menu->addMenu(m_recent);
    menu->addAction(m_edit);
    menu->addAction(m_tools);
}

MachineEditor* MachineFileActions::editor() const
{
    return m_editor.data();
}

bool MachineFileActions::closeEditorThen(std::function<void()> then)
{
    if (!m_editor || !m_editor->isModified()) {
        if (m_editor)
            m_editor->close();
        return true;
    }
    m_editor->show();
    m_editor->raise();
    m_editor->activateWindow();
    m_editor->closeThen(std::move(then));
    return false;
}

void MachineFileActions::setCurrentMachine(const QString& path)
{
    m_current = path;
}

QString MachineFileActions::currentMachine() const
{
    // The machine the window runs, however it was opened (File menu, --machine, the demo).
    if (m_context && m_context->hasMachineFile() && !m_context->machinePath().isEmpty())
        return m_context->machinePath();
    return m_current;
}

MachineEditor* MachineFileActions::showEditor(MachineEditor* editor)
{
    if (m_editor) // one editor at a time: the one open may hold unsaved changes
        m_editor->close();
    if (m_editor && m_editor->isVisible()) { // the operator is asked about its changes first
        delete editor;
        m_editor->raise();
        return m_editor;
    }
    m_editor = editor;
    editor->setAttribute(Qt::WA_DeleteOnClose);
    connect(editor, &MachineEditor::saved, this,
            [this, editor](const QString& path) { onSaved(editor, path); });
    connect(editor, &MachineEditor::reopenRequested, this,
            [this, editor](const QString& path) { reopen(editor, path); });
    editor->resize(editor->sizeHint());
    editor->show();
    editor->raise();
    editor->activateWindow();
    return editor;
}

void MachineFileActions::newMachine()
{
    // "It can start from the controller that is connected now" (issue 19).
    const ModelInfo* model = m_context ? m_context->model() : nullptr;
    if (model && m_context->isConnected())
        showEditor(new MachineEditor(*model, m_context->portName(),
                                     connectionsettings::resetLine(model->id), m_window));
    else
        showEditor(new MachineEditor(m_window));
}

void MachineFileActions::chooseMachineToOpen()
{
    dialogs::openFile(m_window, QStringLiteral("machines"), tr("Open machine"),
                      tr("StepDeck machines (*.machine.json);;JSON files (*.json)"),
                      [this](const QString& path) { open(path); });
}

void MachineFileActions::editMachine()
{
    auto edit = [this](const QString& path) {
        auto* editor = new MachineEditor(m_window);
        editor->openFile(path); // an invalid file: the editor says why
        showEditor(editor);
    };
    if (!currentMachine().isEmpty()) {
        edit(currentMachine());
    } else if (m_context && m_context->isConnectionMachine()) {
        // The connection bar's machine of one (issue 28, item 0): its axes as they are now,
        // saved as a machine file of its own, which then opens in its place.
        auto* editor = new MachineEditor(m_window);
        editor->startFrom(m_context->machine()->description());
        connect(editor, &MachineEditor::saved, this, &MachineFileActions::open);
        showEditor(editor);
    } else
        dialogs::openFile(m_window, QStringLiteral("machines"), tr("Edit machine"),
                          tr("StepDeck machines (*.machine.json);;JSON files (*.json)"), edit);
}

void MachineFileActions::onSaved(MachineEditor* editor, const QString& path)
{
    recentmachines::add(path);
    rebuildRecentMenu();
    if (!m_context || !m_context->hasMachineFile() || m_context->machinePath().isEmpty() ||
        QFileInfo(path) != QFileInfo(m_context->machinePath()))
        return;
    // The running machine was built from the file as it was: saving does not change it.
    const QString text =
        tr("Saved. The open machine \"%1\" still runs on the description it was opened with: "
           "re-open it to use the saved file.")
            .arg(m_context->machine()->description().name);
    editor->offerReopen(text);
    Q_EMIT openMachineSaved(text);
}

void MachineFileActions::reopen(MachineEditor* editor, const QString& path)
{
    const QString refusal = m_reopenMachine ? m_reopenMachine(path) : tr("not possible here");
    if (refusal.isEmpty())
        editor->showNote(tr("Machine re-opened from the saved file: its positions are unknown "
                            "until the axes are referenced again."),
                         false);
    else
        editor->showNote(tr("Not re-opened: %1").arg(refusal), true);
}

void MachineFileActions::open(const QString& path)
{
    recentmachines::add(path);
    rebuildRecentMenu();
    Q_EMIT openRequested(QFileInfo(path).absoluteFilePath());
}

void MachineFileActions::rebuildRecentMenu()
{
    m_recent->clear();
    const QStringList paths = recentmachines::list();
    for (int i = 0; i < paths.size(); ++i) {
        const QString path = paths.at(i);
        QAction* a = m_recent->addAction(
            QStringLiteral("&%1 %2").arg(i + 1).arg(
                QFileInfo(path).fileName().replace(QLatin1Char('&'), QStringLiteral("&&"))),
            this, [this, path] { open(path); });
        a->setData(path);
        a->setToolTip(path);
        a->setStatusTip(path);
    }
    if (paths.isEmpty()) {
        m_recent->addAction(tr("No recent machines"))->setEnabled(false);
        return;
    }
    m_recent->addSeparator();
    m_recent->addAction(tr("Clear list"), this, [this] {
        recentmachines::clear();
        rebuildRecentMenu();
    });
}

} // namespace stepdeck::ui
