#include "StatusPanel.h"
#include "common/IfChanged.h"
#include "common/LedIndicator.h"
#include "machine/MachineContext.h"
#include "status/AxisStatusList.h"
#include "status/DigitalIoGroup.h"
#include "status/RawWordView.h"
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QProgressBar>
#include <QScrollArea>

namespace stepdeck::ui {

namespace {
struct FlagText
{
    const char* key;
    const char* label;
    const char* tip;
};
// Normalised machine flags (model/MachineStatus.h), the same for every model.
const FlagText kMachineFlags[] = {
    {"driveOn", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Drive on"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "The motors are powered.")},
    {"spindleOn", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Spindle on"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "The spindle output is on.")},
    {"busy", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Busy"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "An axis is moving.")},
    {"overTemperature", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Over-temperature"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel",
                       "The controller reports over-temperature; the drivers may switch off.")},
    {"setupIncomplete", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Setup incomplete"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel",
                       "Speeds and acceleration have not all been written; moves are refused.")},
    {"panic", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Emergency stop"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel",
                       "Emergency stop active: panic button or host panic stop.")},
    {"commFault", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Comm fault"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Replies are missing or the link is lost.")},
    {"motionUnconfirmed", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Motion unconfirmed"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel",
                       "The controller did not confirm that the machine stands still (a move "
                       "never reported its arrival, or the link was lost while it ran): it may "
                       "still be moving.")},
    {"startButton", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Start button"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel",
                       "The start button on the controller is pressed.")},
    {"doorOpen", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Door open"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel",
                       "The door switch reports the door open (grey: not reported yet).")},
};
const FlagText kAxisFlags[] = {
    {"moving", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Moving"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel",
                       "Positioning, feed, reference or velocity move")},
    {"jogging", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Jog"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Jogging at a non-zero rate")},
    {"limit", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Limit"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "A limit switch of this axis is active")},
    {"refSwitch", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Ref. switch"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "The reference switch is active")},
    {"referenced", QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel", "Referenced"),
     QT_TRANSLATE_NOOP("stepdeck::ui::StatusPanel",
                       "Referenced since the last panic, reset or reconnect")},
};
} // namespace

StatusPanel::StatusPanel(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_body(new QVBoxLayout(this))
{
    m_body->setContentsMargins(0, 0, 0, 0);
    connect(context, &MachineContext::modelChanged, this, &StatusPanel::rebuild);
    connect(context->session(), &ControllerSession::statusChanged, this, &StatusPanel::onStatus);
    connect(context->session(), &ControllerSession::linkStateChanged, this,
            [this] { onStatus(m_context->status()); });
    rebuild();
}

void StatusPanel::rebuild()
{
    // The viewport's filter goes first: QScrollArea's destructor would otherwise hand the
    // half-destroyed viewport's events to eventFilter() (UBSan: not a QAbstractScrollArea).
    if (m_viewport)
        m_viewport->removeEventFilter(this);
    m_viewport = nullptr;
    delete m_content;
    m_content = nullptr;
    m_machine.clear();
    m_machineOrder.clear();
    m_machineGroup = nullptr;
    m_machineGrid = nullptr;
    m_axes.clear();
    m_axisList = nullptr;
    m_words.clear();
    m_genericRaw = nullptr;
    m_io = nullptr;
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* inner = new QWidget(scroll);
    auto* v = new QVBoxLayout(inner);
    v->addWidget(buildMachineGroup());
    addAxesAndWords(v, inner);
    v->addWidget(buildTemperatureGroup());
    v->addStretch(1);
    scroll->setWidget(inner);
    m_content = scroll;
    m_body->addWidget(scroll);
    m_viewport = scroll->viewport();
    m_viewport->installEventFilter(this); // machine lamps: two columns if they fit
    arrangeColumns();
    onStatus(m_context->status());
}

void StatusPanel::addAxesAndWords(QVBoxLayout* v, QWidget* inner)
{
    const ModelInfo* model = m_context->model();
    const QList<Axis> axes = m_context->axes();
    QList<StatusWordInfo> words;
    if (model && model->presentation.statusWords)
        words = model->presentation.statusWords(axes);
    // Up to kGridAxes axes fit the lamp grid; a bus of more drives gets a filtered list with
    // one drive's words below it (issue 32, step 5).
    QList<StatusWordInfo> axisWords;
    if (axes.size() > kGridAxes) {
        for (const StatusWordInfo& w : std::as_const(words)) {
            if (w.axis)
                axisWords << w;
        }
        m_axisList = new AxisStatusList(m_context, axisWords, inner);
        v->addWidget(m_axisList, 1);
    } else {
        v->addWidget(buildAxesGroup());
    }
    const Capabilities caps = m_context->capabilities();
    if (caps.digitalInputs > 0 || caps.digitalOutputs > 0) {
        m_io = new DigitalIoGroup(m_context, caps.digitalInputs, caps.digitalOutputs, inner);
        v->addWidget(m_io);
    }
    if (model && model->presentation.statusWords) {
        for (StatusWordInfo info : std::as_const(words)) {
            if (m_axisList && info.axis)
                continue; // the list's view shows the chosen drive's
            if (info.axis)
                info.title =
                    tr("%1: %2").arg(m_context->controllerAxisName(*info.axis), info.title);
            auto* view = new RawWordView(info, inner);
            m_words << view;
            v->addWidget(view);
        }
    } else {
        auto* group = new QGroupBox(tr("Raw status"), inner);
        m_genericRaw = new QLabel(group);
        m_genericRaw->setTextInteractionFlags(Qt::TextSelectableByMouse);
        (new QVBoxLayout(group))->addWidget(m_genericRaw);
        v->addWidget(group);
    }
}

QWidget* StatusPanel::buildMachineGroup()
{
    auto* group = new QGroupBox(tr("Machine"));
    m_machineGroup = group;
    m_machineGrid = new QGridLayout(group);
    m_machineColumns = 0;
    const Capabilities caps = m_context->capabilities();
    for (const FlagText& f : kMachineFlags) {
        const QString key = QString::fromLatin1(f.key);
        // A lamp for what the model has (issue 31: laser axes showed Spindle and
        // Over-temperature, which they never report).
        if ((key == QLatin1String("startButton") && !caps.startButton) ||
            (key == QLatin1String("doorOpen") && !caps.doorSwitch) ||
            (key == QLatin1String("spindleOn") && !caps.spindle) ||
            (key == QLatin1String("overTemperature") && !caps.temperature))
            continue;
        auto* lamp = new LedIndicator(tr(f.label), group);
        lamp->setToolTip(tr(f.tip));
        lamp->setObjectName(key);
        m_machine.insert(key, lamp);
        m_machineOrder << lamp;
    }
    return group;
}

void StatusPanel::arrangeColumns()
{
    if (!m_content || !m_machineGrid)
        return;
    // The room the scroll area offers, not the groups' own widths (which two columns widen).
    const QMargins inner = m_content->widget()->layout()->contentsMargins();
    const int room = m_content->viewport()->width() - inner.left() - inner.right();
    for (RawWordView* view : std::as_const(m_words))
        view->fitWidth(room);
    int cell = 0;
    for (const LedIndicator* lamp : std::as_const(m_machineOrder))
        cell = qMax(cell, lamp->sizeHint().width());
    const QMargins grid = m_machineGrid->contentsMargins();
    const int frame = m_machineGroup->width() - m_machineGroup->contentsRect().width();
    const int inside = room - frame - grid.left() - grid.right();
    const int columns = inside >= 2 * cell + m_machineGrid->horizontalSpacing() ? 2 : 1;
    if (columns == m_machineColumns)
        return;
    m_machineColumns = columns;
    for (LedIndicator* lamp : std::as_const(m_machineOrder))
        m_machineGrid->removeWidget(lamp);
    for (int i = 0; i < m_machineOrder.size(); ++i)
        m_machineGrid->addWidget(m_machineOrder.at(i), i / columns, i % columns);
}

bool StatusPanel::eventFilter(QObject* watched, QEvent* event)
{
    if (m_viewport && watched == m_viewport && event->type() == QEvent::Resize)
        arrangeColumns();
    return QWidget::eventFilter(watched, event);
}

QWidget* StatusPanel::buildAxesGroup()
{
    // One row per flag, one column per axis: as narrow as a dock at 1366x768 allows, in
    // German too (issue 16: five flag columns were cut off).
    auto* group = new QGroupBox(tr("Axes"));
    auto* grid = new QGridLayout(group);
    int column = 1;
    for (Axis axis : m_context->axes()) {
        auto* name = new QLabel(m_context->controllerAxisName(axis), group);
        QFont bold = name->font();
        bold.setBold(true);
        name->setFont(bold);
        grid->addWidget(name, 0, column++, Qt::AlignCenter);
    }
    int row = 1;
    for (const FlagText& f : kAxisFlags) {
        auto* label = new QLabel(tr(f.label), group);
        label->setToolTip(tr(f.tip));
        grid->addWidget(label, row, 0);
        column = 1;
        for (Axis axis : m_context->axes()) {
            auto* lamp = new LedIndicator({}, group);
            lamp->setToolTip(
                QStringLiteral("%1: %2").arg(m_context->controllerAxisName(axis), tr(f.tip)));
            m_axes[axis].insert(QString::fromLatin1(f.key), lamp);
            grid->addWidget(lamp, row, column++, Qt::AlignCenter);
        }
        ++row;
    }
    grid->setColumnStretch(column, 1);
    return group;
}

QWidget* StatusPanel::buildTemperatureGroup()
{
    auto* group = new QGroupBox(tr("Controller"));
    auto* grid = new QGridLayout(group);
    m_temperature = new QLabel(group);
    QFont big = m_temperature->font();
    big.setPointSizeF(big.pointSizeF() * 1.6);
    big.setBold(true);
    m_temperature->setFont(big);
    m_temperatureBar = new QProgressBar(group);
    m_temperatureBar->setRange(0, 70);
    m_temperatureBar->setTextVisible(false);
    m_temperatureBar->setMaximumHeight(12);
    m_temperatureNote = new QLabel(group);
    m_temperatureNote->setWordWrap(true);
    m_counters = new QLabel(group);
    m_counters->setWordWrap(true); // at the panel's end: wrapping moves nothing below
    m_drives = new QLabel(group);
    m_drives->setWordWrap(true);
    m_firmware = new QLabel(group);
    m_firmware->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_firmware->setWordWrap(true);
    auto* temperatureLabel = new QLabel(tr("Temperature:"), group);
    grid->addWidget(temperatureLabel, 0, 0);
    grid->addWidget(m_temperature, 0, 1);
    grid->addWidget(m_temperatureBar, 1, 0, 1, 2);
    grid->addWidget(m_temperatureNote, 2, 0, 1, 2);
    grid->addWidget(m_counters, 3, 0, 1, 2);
    grid->addWidget(m_drives, 4, 0, 1, 2);
    grid->addWidget(m_firmware, 5, 0, 1, 2);
    const bool hasTemperature = m_context->capabilities().temperature;
    temperatureLabel->setVisible(hasTemperature);
    m_temperature->setVisible(hasTemperature);
    m_temperatureBar->setVisible(hasTemperature);
    return group;
}

RawWordView* StatusPanel::rawWord(const QString& key) const
{
    QList<RawWordView*> views = m_words;
    if (m_axisList)
        views += m_axisList->wordViews();
    for (RawWordView* view : std::as_const(views)) {
        if (view->info().key == key)
            return view;
    }
    return nullptr;
}

QString StatusPanel::temperatureText() const
{
    return m_temperature ? m_temperature->text() : QString();
}

QString StatusPanel::temperatureNote() const
{
    return m_temperatureNote ? m_temperatureNote->text() : QString();
}

QString StatusPanel::firmwareText() const
{
    return m_firmware ? m_firmware->text() : QString();
}

QString StatusPanel::countersText() const
{
    return m_counters ? m_counters->text() : QString();
}

void StatusPanel::onStatus(const MachineStatus& s)
{
    const bool live = m_context->session()->isCreated() &&
                      m_context->session()->linkState() == LinkState::Connected;
    using S = LedIndicator::State;
    auto set = [&](const char* key, bool on, S onState) {
        if (LedIndicator* lamp = m_machine.value(QString::fromLatin1(key)))
            lamp->setState(!live ? S::Unknown : on ? onState : S::Off);
    };
    set("driveOn", s.driveOn, S::On);
    set("spindleOn", s.spindleOn, S::On);
    set("busy", s.busy, S::On);
    set("overTemperature", s.overTemperature, S::Fault);
    set("setupIncomplete", s.setupIncomplete, S::Warning);
    set("panic", s.panic, S::Fault);
    if (LedIndicator* lamp = m_machine.value(QStringLiteral("motionUnconfirmed")))
        lamp->setOn(s.motionUnconfirmed, S::Fault); // stays meaningful after the link is lost
    if (LedIndicator* lamp = m_machine.value(QStringLiteral("commFault")))
        lamp->setOn(s.commFault, S::Fault); // meaningful when the link is down, too
    set("startButton", s.startButton.value_or(false), S::On);
    if (LedIndicator* lamp = m_machine.value(QStringLiteral("startButton"));
        lamp && live && !s.startButton.has_value())
        lamp->setState(S::Unknown);
    set("doorOpen", s.doorOpen.value_or(false), S::Warning);
    if (LedIndicator* lamp = m_machine.value(QStringLiteral("doorOpen"));
        lamp && live && !s.doorOpen.has_value())
        lamp->setState(S::Unknown);

    for (auto it = m_axes.cbegin(); it != m_axes.cend(); ++it) {
        const AxisStatus a = s.axes.value(it.key());
        const QMap<QString, LedIndicator*>& lamps = it.value();
        auto axisSet = [&](const char* key, bool on, S onState) {
            lamps.value(QString::fromLatin1(key))
                ->setState(!live ? S::Unknown
                           : on  ? onState
                                 : S::Off);
        };
        axisSet("moving", a.moving, S::On);
        axisSet("jogging", a.jogging, S::On);
        axisSet("limit", a.limitSwitch, S::Fault);
        axisSet("refSwitch", a.referenceSwitch, S::Warning);
        axisSet("referenced", a.referenced, S::On);
    }
    if (m_axisList)
        m_axisList->setStatus(s, live);
    for (RawWordView* view : std::as_const(m_words))
        view->setValue(live ? s.raw.value(view->info().key) : QVariant());
    if (m_genericRaw) {
        QStringList lines;
        for (auto it = s.raw.cbegin(); it != s.raw.cend(); ++it)
            lines << QStringLiteral("%1: 0x%2")
                         .arg(it.key(), QString::number(it.value().toULongLong(), 16).toUpper());
        m_genericRaw->setText(lines.isEmpty() ? tr("no raw words") : lines.join(QLatin1Char('\n')));
    }
    updateTemperature(s);
    m_counters->setText(tr("Comm faults: %1    Resyncs: %2    Poll rate: %3 Hz")
                            .arg(s.commFaultCount)
                            .arg(s.resyncCount)
                            .arg(m_context->session()->pollRateHz(), 0, 'f', 1));
    showDrives(s);
    m_firmware->setText(s.deviceFirmware.isEmpty() ? QString()
                                                   : tr("Firmware: %1").arg(s.deviceFirmware));
    m_firmware->setVisible(!s.deviceFirmware.isEmpty());
    if (m_io)
        m_io->setStatus(s, live);
}

// A bus's drives as lines under the counters (the list has a Drive column instead).
void StatusPanel::showDrives(const MachineStatus& s)
{
    QStringList drives;
    if (s.drives.size() > 1 && !m_axisList) { // the list has a drive column
        for (const DriveStatus& d : s.drives)
            drives << tr("Drive %1: %2 %3")
                          .arg(d.address)
                          .arg(d.responding ? tr("responding") : tr("NOT RESPONDING"), d.detail);
    }
    m_drives->setText(drives.join(QLatin1Char('\n')));
    m_drives->setVisible(!drives.isEmpty());
}

void StatusPanel::updateTemperature(const MachineStatus& s)
{
    const bool live = m_context->isConnected();
    if (!live || !s.temperatureCelsius) {
        m_temperature->setText(QStringLiteral("\u2013 \u00b0C"));
        m_temperatureBar->setValue(0);
        m_temperatureNote->setText(QString());
        return;
    }
    const double t = *s.temperatureCelsius;
    m_temperature->setText(QStringLiteral("%1 \u00b0C").arg(t, 0, 'f', 0));
    m_temperatureBar->setValue(qBound(0, int(t), 70));
    QString colour = QStringLiteral("#43a047");
    QString note;
    if (s.overTemperature || t >= kTemperatureLimitC) {
        colour = QStringLiteral("#e53935");
        note = tr("Over-temperature: the drivers may switch off. Stop and let the controller "
                  "cool down.");
    } else if (t >= kTemperatureWarningC) {
        colour = QStringLiteral("#ffb300");
        note = tr("Warning: approaching the %1 °C over-temperature limit.")
                   .arg(kTemperatureLimitC, 0, 'f', 0);
    }
    setStyleSheetIfChanged(m_temperatureBar,
                           QStringLiteral("QProgressBar::chunk { background: %1; }").arg(colour));
    setStyleSheetIfChanged(m_temperature, QStringLiteral("QLabel { color: %1; }").arg(colour));
    m_temperatureNote->setText(note);
}

} // namespace stepdeck::ui
