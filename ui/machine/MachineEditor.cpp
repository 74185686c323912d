#include "MachineEditor.h"
#include "AxesTable.h"
#include "ControllersTable.h"
#include "EditorTable.h"
#include "common/ElidedLabel.h"
#include "protocols/Registry.h"
#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace stepdeck::ui {

using machine::MachineDescription;
using machine::MachineFile;
using machine::MachineFileError;

namespace {
// The look of an invalid cell, as the setup page marks an invalid field; a choice gets a
// border too (its background alone hardly shows).
const QString kInvalidSheet = QStringLiteral("background: #ffcdd2; color: #8e0000;");
const QString kInvalidChoiceSheet =
    QStringLiteral("QComboBox { background: #ffcdd2; color: #8e0000; border: 2px solid #c62828; }");

// A row of a title and buttons above a table.
QHBoxLayout* titleRow(const QString& title, const QList<QPushButton*>& buttons)
{
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(title.toHtmlEscaped())));
    row->addStretch(1);
    for (QPushButton* b : buttons)
        row->addWidget(b);
    return row;
}
} // namespace

MachineEditor::MachineEditor(QWidget* parent) : QWidget(parent, Qt::Window)
{
    build();
    MachineDescription empty;
    empty.name = tr("New machine");
    machine::MachineController c;
    c.id = QStringLiteral("controller1");
    c.modelId = models().value(0).id;
    c.port = QStringLiteral("sim");
    empty.controllers << c;
    setMachine(empty);
}

MachineEditor::MachineEditor(const ModelInfo& model, const QString& port,
                             std::optional<LineSettings::ResetLine> resetLine, QWidget* parent)
    : QWidget(parent, Qt::Window)
{
    build();
    startFromController(model, port, resetLine);
}

// The spindle scale and the cross-controller switch beside the name: one row, the tables keep
// the height.
QHBoxLayout* MachineEditor::buildNameRow()
{
    auto* nameRow = new QHBoxLayout;
    nameRow->addWidget(m_name, 1);
    auto* maxRpmLabel = new QLabel(tr("Spindle max rpm"), this);
    maxRpmLabel->setBuddy(m_maxRpm);
    nameRow->addWidget(maxRpmLabel);
    nameRow->addWidget(m_maxRpm);
    nameRow->addWidget(m_crossFeed);
    return nameRow;
}

void MachineEditor::build()
{
    setObjectName(QStringLiteral("machineEditor"));
    setWindowModality(Qt::NonModal); // STOP and PANIC stay reachable (ui/common/Dialogs.h)
    m_name = new QLineEdit(this);
    m_name->setObjectName(QStringLiteral("machineName"));
    m_maxRpm = new QLineEdit(this);
    m_maxRpm->setObjectName(QStringLiteral("machineMaxRpm"));
    m_maxRpm->setPlaceholderText(tr("none"));
    m_maxRpm->setMaximumWidth(fontMetrics().horizontalAdvance(QStringLiteral("0")) * 12);
    m_maxRpm->setToolTip(tr("The spindle speed in rpm that the controller's full spindle range "
                            "stands for: a program's S is then in rpm (S12000 of 24000 is half "
                            "the range). Empty: S is sent in the controller's own units."));
    m_crossFeed = new QCheckBox(tr("Feed across controllers"), this);
    m_crossFeed->setObjectName(QStringLiteral("machineCrossControllerFeed"));
    m_crossFeed->setToolTip(tr("Allow feed moves (G1, G2, G3) whose axes sit on several "
                               "controllers. They start together but share no clock, so their "
                               "path is only approximate; off, the program check refuses them."));
    m_controllers = new ControllersTable(this);
    m_axes = new AxesTable(this);
    m_message = new ElidedLabel(this, 1);
    m_message->setObjectName(QStringLiteral("machineMessage"));
    m_message->setMinimumTextWidth(200);

    auto* addController = new QPushButton(tr("Add controller"), this);
    auto* removeController = new QPushButton(tr("Remove controller"), this);
    auto* addAxis = new QPushButton(tr("Add axis"), this);
    auto* removeAxis = new QPushButton(tr("Remove axis"), this);
    connect(addController, &QPushButton::clicked, m_controllers, &ControllersTable::addController);
    connect(removeController, &QPushButton::clicked, m_controllers,
            &ControllersTable::removeCurrentController);
    connect(addAxis, &QPushButton::clicked, m_axes, &AxesTable::addAxis);
    connect(removeAxis, &QPushButton::clicked, m_axes, &AxesTable::removeCurrentAxis);

    auto* form = new QFormLayout;
    form->addRow(tr("Machine name"), buildNameRow());
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(titleRow(tr("Controllers"), {addController, removeController}));
    layout->addWidget(m_controllers);
    layout->addLayout(titleRow(tr("Axes"), {addAxis, removeAxis}));
    layout->addWidget(m_axes, 1);
    layout->addWidget(m_message);
    layout->addWidget(buildButtons());

    connect(m_name, &QLineEdit::textEdited, this, &MachineEditor::revalidate);
    connect(m_maxRpm, &QLineEdit::textEdited, this, &MachineEditor::revalidate);
    connect(m_crossFeed, &QCheckBox::toggled, this, &MachineEditor::revalidate);
    connect(m_controllers, &EditorTable::edited, this, [this] {
        m_axes->setControllerAxes(m_controllers->controllerAxes());
        revalidate();
    });
    connect(m_axes, &EditorTable::edited, this, &MachineEditor::revalidate);
    connect(m_controllers, &ControllersTable::idRenamed, m_axes, &AxesTable::renameController);
    connect(m_controllers, &ControllersTable::idsChanged, this,
            [this] { m_axes->setControllerIds(m_controllers->ids()); });
}

QWidget* MachineEditor::buildButtons()
{
    auto* box = new QWidget(this);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(0, 0, 0, 0);
    auto* open = new QPushButton(tr("Open\u2026"), box);
    auto* save = new QPushButton(tr("Save"), box);
    save->setObjectName(QStringLiteral("saveButton"));
    auto* saveAs = new QPushButton(tr("Save as\u2026"), box);
    auto* close = new QPushButton(tr("Close"), box);
    open->setShortcut(QKeySequence::Open); // in this window only: STOP keeps Esc
    save->setShortcut(QKeySequence::Save);
    connect(open, &QPushButton::clicked, this, &MachineEditor::chooseFile);
    connect(save, &QPushButton::clicked, this, &MachineEditor::save);
    connect(saveAs, &QPushButton::clicked, this, &MachineEditor::saveAs);
    connect(close, &QPushButton::clicked, this, &QWidget::close);
    m_reopen = new QPushButton(tr("Re-open machine"), box);
    m_reopen->setObjectName(QStringLiteral("reopenMachineButton"));
    m_reopen->setToolTip(tr("Close the machine the window runs and open it again from the saved "
                            "file. Its positions are unknown until the axes are referenced "
                            "again, as after any reconnect."));
    m_reopen->hide(); // until the open machine's file was saved (offerReopen)
    connect(m_reopen, &QPushButton::clicked, this, [this] { Q_EMIT reopenRequested(m_path); });
    for (QPushButton* b : {open, save, saveAs})
        row->addWidget(b);
    row->addStretch(1);
    row->addWidget(m_reopen);
    row->addWidget(close);
    return box;
}

void MachineEditor::setMachine(const MachineDescription& machine, const QString& path)
{
    m_path = path;
    m_subroutineFolder = machine.subroutineFolder;
    m_subroutineFolderPath = machine.subroutineFolderPath;
    m_limits = machine.limits;
    m_toolLength = machine.toolLength;
    m_spindleLaser = machine.spindle.laser;
    m_reopen->hide(); // another file: offered again once it is saved
    m_name->setText(machine.name);
    m_maxRpm->setText(machine.spindle.maxRpm ? QString::number(*machine.spindle.maxRpm, 'g',
                                                               QLocale::FloatingPointShortest)
                                             : QString());
    {
        const QSignalBlocker quiet(m_crossFeed); // revalidated below
        m_crossFeed->setChecked(machine.crossControllerFeed);
    }
    m_axes->setAxes({}); // first: the new controllers' ids go to no old row
    m_controllers->setControllers(machine.controllers);
    m_axes->setAxes(machine.axes);
    m_axes->setControllerAxes(m_controllers->controllerAxes());
    revalidate();
    setModified(false);
}

void MachineEditor::startFrom(const MachineDescription& machine)
{
    setMachine(machine);
    setModified(true); // not saved anywhere yet
}

void MachineEditor::startFromController(const ModelInfo& model, const QString& port,
                                        std::optional<LineSettings::ResetLine> resetLine)
{
    MachineDescription machine = MachineDescription::singleController(model, port);
    if (model.capabilities.resetLine)
        machine.controllers.first().resetLine = resetLine;
    setMachine(machine);
    setModified(true); // not saved anywhere yet
}

bool MachineEditor::readMachine(MachineDescription* out, MachineFileError* error) const
{
    out->name = m_name->text().trimmed();
    out->crossControllerFeed = m_crossFeed->isChecked();
    out->subroutineFolder = m_subroutineFolder;
    out->subroutineFolderPath = m_subroutineFolderPath;
    out->limits = m_limits;
    out->toolLength = m_toolLength;
    out->spindle.laser = m_spindleLaser;
    return m_controllers->read(&out->controllers, error) && m_axes->read(&out->axes, error) &&
           readDecimal(m_maxRpm, QStringLiteral("spindle.maxRpm"), true, &out->spindle.maxRpm,
                       error) &&
           MachineFile::validate(*out, error);
}

std::optional<MachineDescription> MachineEditor::machine() const
{
    MachineDescription d;
    if (!readMachine(&d, nullptr))
        return std::nullopt;
    return d;
}

void MachineEditor::revalidate()
{
    MachineDescription d;
    m_error = {};
    setModified(true);
    if (readMachine(&d, &m_error)) {
        mark({});
        QStringList names;
        for (const machine::MachineAxis& a : d.axes)
            names << a.name;
        showMessage(tr("Valid machine with the axes %1").arg(names.join(QLatin1Char(' '))), false);
        return;
    }
    mark(cellsOf(m_error.field));
    showMessage(m_error.text(), true);
}

QList<QWidget*> MachineEditor::cellsOf(const QString& field) const
{
    static const QRegularExpression row(QStringLiteral(R"(^(controllers|axes)\[(\d+)\]\.(.+)$)"));
    const QRegularExpressionMatch m = row.match(field);
    if (field == QLatin1String("name"))
        return {m_name};
    if (field.startsWith(QLatin1String("spindle")))
        return {m_maxRpm};
    if (field == QLatin1String("controllers"))
        return {m_controllers};
    if (field == QLatin1String("axes"))
        return {m_axes};
    if (!m.hasMatch())
        return {};
    const int index = m.captured(2).toInt();
    const QString key = m.captured(3);
    if (m.captured(1) == QLatin1String("controllers")) // "axes.X": the bus address cell
        return m_controllers->cells(index, key.section(QLatin1Char('.'), 0, 0));
    return m_axes->cells(index, key);
}

void MachineEditor::mark(const QList<QWidget*>& cells)
{
    for (const QPointer<QWidget>& w : std::as_const(m_marked)) {
        if (w && !cells.contains(w.data()))
            w->setStyleSheet(QString());
    }
    m_marked.clear();
    for (QWidget* w : cells) {
        if (w != m_controllers && w != m_axes) // a whole table is named by the message
            w->setStyleSheet(w->inherits("QComboBox") ? kInvalidChoiceSheet : kInvalidSheet);
        m_marked << w;
    }
}

QList<QWidget*> MachineEditor::markedCells() const
{
    QList<QWidget*> list;
    for (const QPointer<QWidget>& w : m_marked) {
        if (w)
            list << w.data();
    }
    return list;
}

void MachineEditor::showMessage(const QString& text, bool isError)
{
    m_message->setText(text);
    m_message->setStyleSheet(isError ? QStringLiteral("color: #b71c1c;") : QString());
}

void MachineEditor::offerReopen(const QString& note)
{
    showMessage(note, false);
    m_reopen->show();
}

QString MachineEditor::messageText() const
{
    return m_message->text();
}

void MachineEditor::setModified(bool modified)
{
    m_modified = modified;
    const QString name = m_name->text().trimmed();
    setWindowTitle(tr("Machine editor \u2013 %1[*]").arg(name.isEmpty() ? tr("unnamed") : name));
    setWindowModified(modified);
}

} // namespace stepdeck::ui
