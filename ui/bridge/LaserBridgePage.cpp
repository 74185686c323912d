#include "LaserBridgePage.h"
#include "common/ElidedLabel.h"
#include "connection/PortScanner.h"
#include "machine/MachineContext.h"
#include "transport/Transport.h"
#include "transport/TransportFactory.h"
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepdeck::ui {

using bridge::LaserBridge;
using bridge::LaserBridgeConfig;

namespace {
const QList<Axis> kLaserAxes{Axis::X, Axis::Y, Axis::Z};
enum Column { ColLaser, ColAxis, ColState, ColTarget, ColReferenced, ColAnswer, ColCount };
} // namespace

LaserBridgePage::LaserBridgePage(MachineContext* context, PortScanner* ports, QWidget* parent)
    : QWidget(parent), m_context(context), m_ports(ports), m_port(new QComboBox(this)),
      m_scale(new QDoubleSpinBox(this)), m_doorInput(new QSpinBox(this)),
      m_start(new QPushButton(tr("Start bridge"), this)),
      m_stop(new QPushButton(tr("Stop bridge"), this)), m_state(new ElidedLabel(this, 2)),
      m_table(new QTableWidget(0, ColCount, this)), m_log(new QPlainTextEdit(this))
{
    m_table->setHorizontalHeaderLabels({tr("Laser axis"), tr("Axis"), tr("State"), tr("Target"),
                                        tr("Referenced"), tr("Last answer")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(2000);
    m_log->setObjectName(QStringLiteral("laserBridgeLog"));
    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    m_log->setFont(mono);

    auto* right = new QWidget(this);
    auto* rv = new QVBoxLayout(right);
    rv->setContentsMargins(0, 0, 0, 0);
    rv->addWidget(m_table, 1);
    rv->addWidget(new QLabel(tr("Laser frames and answers:"), right));
    rv->addWidget(m_log, 2);
    // The form scrolls: the page sits in the bottom dock area and must not raise the main
    // window's minimum height (1366x768 screens).
    auto* formScroll = new QScrollArea(this);
    formScroll->setWidget(buildForm());
    formScroll->setWidgetResizable(true);
    formScroll->setFrameShape(QFrame::NoFrame);
    formScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    formScroll->setMinimumWidth(formScroll->widget()->minimumSizeHint().width() +
                                formScroll->verticalScrollBar()->sizeHint().width());
    m_table->setMinimumHeight(60);
    m_log->setMinimumHeight(60);
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(formScroll);
    splitter->addWidget(right);
    splitter->setStretchFactor(1, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(splitter);

    connect(m_start, &QPushButton::clicked, this, &LaserBridgePage::startBridge);
    connect(m_stop, &QPushButton::clicked, this, &LaserBridgePage::stopBridge);
    connect(context, &MachineContext::modelChanged, this, [this] {
        stopBridge();
        rebuildAxisChoices();
    });
    connect(context->session(), &ControllerSession::linkStateChanged, this, [this](LinkState s) {
        if (s != LinkState::Connected)
            stopBridge();
        updateControls();
    });
    rebuildAxisChoices();
    setState(tr("Not running."));
    updateControls();
}

LaserBridgePage::~LaserBridgePage()
{
    delete m_bridge; // closes the laser port
}

QWidget* LaserBridgePage::buildForm()
{
    // Not the dock's title again (issue 31: "Laser bridge" showed twice, one under the other).
    auto* box = new QGroupBox(tr("Laser port and axes"), this);
    auto* v = new QVBoxLayout(box);
    auto* intro = new QLabel(tr("StepDeck answers the laser marker's motor-axis frames (RS232, "
                                "9600 8N1) with the connected controller."),
                             box);
    intro->setWordWrap(true);
    v->addWidget(intro);
    auto* form = new QFormLayout;
    m_port->setEditable(true);
    fillPorts();
    m_port->setCurrentText(QString());
    connect(m_ports, &PortScanner::portsChanged, this, &LaserBridgePage::fillPorts);
    m_port->lineEdit()->setPlaceholderText(QStringLiteral("/dev/ttyUSB1"));
    m_port->setToolTip(tr("The serial port cabled to the laser's XYZ-control port"));
    form->addRow(tr("Laser port:"), m_port);
    m_scale->setRange(0.0001, LaserBridgeConfig::kMaxScale);
    m_scale->setDecimals(4);
    m_scale->setValue(1.0);
    m_scale->setToolTip(tr("Controller steps per laser position unit: a target goes to target x "
                           "scale steps from the reference"));
    form->addRow(tr("Steps per laser unit:"), m_scale);
    m_doorInput->setRange(0, 64);
    m_doorInput->setSpecialValueText(tr("none"));
    m_doorInput->setToolTip(tr("A controller input wired to the door switch (set = door open), "
                               "where the controller publishes its inputs"));
    form->addRow(tr("Door switch input:"), m_doorInput);
    v->addLayout(form);

    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("Laser axis"), box), 0, 0);
    grid->addWidget(new QLabel(tr("Controller axis"), box), 0, 1);
    grid->addWidget(new QLabel(tr("Reference direction"), box), 0, 2);
    int row = 1;
    for (Axis laserAxis : kLaserAxes) {
        auto* map = new QComboBox(box);
        auto* home = new QComboBox(box); // filled by rebuildAxisChoices()
        m_map.insert(laserAxis, map);
        m_home.insert(laserAxis, home);
        grid->addWidget(
            new QLabel(tr("%1 (%2)").arg(laser::axisNumber(laserAxis)).arg(axisName(laserAxis)),
                       box),
            row, 0);
        grid->addWidget(map, row, 1);
        grid->addWidget(home, row, 2);
        ++row;
    }
    v->addLayout(grid);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    v->addLayout(buttons);
    // Two lines reserved (full text in the tooltip): the note below never moves.
    m_state->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_state->setObjectName(QStringLiteral("laserBridgeState"));
    v->addWidget(m_state);
    auto* priority = new QLabel(tr("STOP, PANIC and jog keep priority over the bridge: a target "
                                   "the operator stopped is not answered (the laser raises its "
                                   "timeout alarm), and targets that arrive while the operator "
                                   "jogs are dropped."),
                                box);
    priority->setWordWrap(true);
    v->addWidget(priority);
    v->addStretch(1);
    return box;
}

// The scanner's list, refreshed when ports come and go; what the technician typed or chose
// stays in the field (a pty is never listed and is typed).
void LaserBridgePage::fillPorts()
{
    const QString current = m_port->currentText();
    const QSignalBlocker block(m_port);
    m_port->clear();
    for (const PortEntry& entry : m_ports->ports())
        m_port->addItem(entry.label, entry.path);
    m_port->setCurrentText(current);
}

void LaserBridgePage::rebuildAxisChoices()
{
    const QList<Axis> axes = m_context->axes();
    // Some controllers choose the direction of their reference runs themselves (EMIS 9.9),
    // as the reference panel shows too.
    const bool directed = m_context->capabilities().referenceDirection;
    for (Axis laserAxis : kLaserAxes) {
        QComboBox* map = m_map.value(laserAxis);
        map->clear();
        map->addItem(tr("not used"), -1);
        for (Axis a : axes)
            map->addItem(axisName(a), a.index());
        const int same = map->findData(laserAxis.index());
        map->setCurrentIndex(same >= 0 ? same : 0);
        QComboBox* home = m_home.value(laserAxis);
        home->clear();
        if (directed) {
            home->addItem(tr("negative (-1)"), -1);
            home->addItem(tr("positive (+1)"), 1);
            home->setToolTip(QString());
        } else {
            home->addItem(tr("chosen by the controller"), 0);
            home->setToolTip(tr("The controller chooses the direction of its reference run "
                                "itself"));
        }
    }
    updateControls();
}

bool LaserBridgePage::isRunning() const
{
    return m_bridge && m_bridge->isRunning();
}

bool LaserBridgePage::configFromForm(LaserBridgeConfig* config, QString* error) const
{
    LaserBridgeConfig c;
    c.axisMap.clear();
    for (Axis laserAxis : kLaserAxes) {
        const int axis = m_map.value(laserAxis)->currentData().toInt();
        const std::optional<Axis> target = Axis::fromIndex(axis);
        if (!target)
            continue; // "not used"
        c.axisMap.insert(laserAxis, *target);
        if (const int direction = m_home.value(laserAxis)->currentData().toInt(); direction != 0)
            c.homeDirections.insert(*target, direction);
    }
    c.scale = m_scale->value();
    if (m_doorInput->value() > 0)
        c.doorInput = m_doorInput->value();
    *error = c.validate(m_context->capabilities());
    *config = c;
    return error->isEmpty();
}

void LaserBridgePage::startBridge()
{
    if (m_bridge)
        return;
    if (!m_context->isConnected())
        return setState(tr("Connect the controller first."), true);
    // A listed port by its label, or a typed path (ptys are never listed).
    const QString typed = m_port->currentText().trimmed();
    const int listed = m_port->findText(typed);
    const QString port = listed >= 0 ? m_port->itemData(listed).toString() : typed;
    if (port.isEmpty())
        return setState(tr("Choose the laser's port."), true);
    if (port == m_context->portName())
        return setState(tr("The laser's port is the controller's port."), true);
    LaserBridgeConfig config;
    QString error;
    if (!configFromForm(&config, &error))
        return setState(error, true);
    if (config.doorInput && !LaserBridge::doorInputState(m_context->status(), *config.doorInput))
        return setState(tr("This controller publishes no inputs: no door switch input."), true);
    m_table->setRowCount(0);
    m_laserPort = createTransport(port, this);
    m_bridge = new LaserBridge(m_context->session(), m_laserPort, config, this);
    connect(m_bridge, &LaserBridge::logged, this, &LaserBridgePage::appendLog);
    connect(m_bridge, &LaserBridge::axisChanged, this, &LaserBridgePage::showAxis);
    connect(m_bridge, &LaserBridge::started, this, [this] {
        setState(tr("Running: answering the laser on %1.").arg(m_laserPort->description()));
        updateControls();
    });
    connect(m_bridge, &LaserBridge::failed, this, [this](const QString& why) {
        setState(tr("Laser bridge failed: %1").arg(why), true);
        if (m_bridge && !m_bridge->isRunning())
            onFinished();
    });
    connect(m_bridge, &LaserBridge::finished, this, &LaserBridgePage::onFinished);
    setState(tr("Opening %1\u2026").arg(port));
    m_bridge->start();
    updateControls();
}

void LaserBridgePage::stopBridge()
{
    if (m_bridge && !m_stopping) {
        m_stopping = true;
        setState(tr("Stopping\u2026"));
        m_bridge->shutdown();
    }
}

void LaserBridgePage::onFinished()
{
    if (!m_bridge)
        return;
    if (!m_state->property("error").toBool())
        setState(tr("Not running."));
    m_bridge->deleteLater();
    m_laserPort->deleteLater();
    m_bridge = nullptr;
    m_laserPort = nullptr;
    m_stopping = false;
    updateControls();
}

void LaserBridgePage::appendLog(const LaserBridge::LogEntry& entry)
{
    m_log->appendPlainText(LaserBridge::formatLogEntry(entry));
    // A target not answered, a door not reported, a stop that failed: shown at once, whatever
    // the laser was told, and kept until the bridge is started again.
    if (entry.kind == LaserBridge::LogEntry::Kind::Error) {
        setState(tr("At %1: %2").arg(entry.time.toString(QStringLiteral("HH:mm:ss")), entry.text),
                 true);
    }
}

void LaserBridgePage::showAxis(const LaserBridge::AxisView& view)
{
    int row = -1;
    for (int r = 0; r < m_table->rowCount(); ++r) {
        if (m_table->item(r, ColLaser)->data(Qt::UserRole).toInt() == view.laserAxis.index())
            row = r;
    }
    if (row < 0) {
        row = m_table->rowCount();
        m_table->insertRow(row);
        for (int c = 0; c < ColCount; ++c)
            m_table->setItem(row, c, new QTableWidgetItem);
        m_table->item(row, ColLaser)->setData(Qt::UserRole, view.laserAxis.index());
    }
    m_table->item(row, ColLaser)->setText(QString::number(laser::axisNumber(view.laserAxis)));
    m_table->item(row, ColAxis)->setText(axisName(view.controllerAxis));
    QTableWidgetItem* state = m_table->item(row, ColState);
    state->setText(LaserBridge::phaseName(view.phase));
    state->setToolTip(view.failure);
    state->setForeground(view.failure.isEmpty() ? palette().text()
                                                : QBrush(QColor(0xc6, 0x28, 0x28)));
    m_table->item(row, ColTarget)
        ->setText(view.target ? laser::commandText(*view.target) : QStringLiteral("-"));
    m_table->item(row, ColReferenced)->setText(view.referenced ? tr("yes") : tr("no"));
    m_table->item(row, ColAnswer)
        ->setText(view.lastAnswer ? laser::statusText(*view.lastAnswer) : QStringLiteral("-"));
}

void LaserBridgePage::updateControls()
{
    const bool active = m_bridge != nullptr;
    m_start->setEnabled(!active && m_context->isConnected());
    m_stop->setEnabled(active);
    for (QWidget* w : std::initializer_list<QWidget*>{m_port, m_scale, m_doorInput})
        w->setEnabled(!active);
    const bool directed = m_context->capabilities().referenceDirection;
    for (Axis a : kLaserAxes) {
        m_map.value(a)->setEnabled(!active);
        m_home.value(a)->setEnabled(!active && directed);
    }
}

void LaserBridgePage::setState(const QString& text, bool error)
{
    m_state->setText(text);
    m_state->setProperty("error", error);
    m_state->setStyleSheet(error ? QStringLiteral("QLabel { color: #c62828; }") : QString());
}

} // namespace stepdeck::ui
