#include "ConnectionBar.h"
#include "common/ReservedSize.h"
#include "connection/ConnectionSettings.h"
#include "connection/PortScanner.h"
#include "connection/PortWatcher.h"
#include "machine/MachineContext.h"
#include "protocols/Registry.h"
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>

namespace stepdeck::ui {

namespace {
const QString kSim = QStringLiteral("sim");
}

ConnectionBar::ConnectionBar(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_scanner(new PortScanner(this)),
      m_watcher(new PortWatcher(this)), m_model(new QComboBox(this)), m_port(new QComboBox(this)),
      m_resetLabel(new QLabel(tr("Reset:"), this)), m_resetLine(new QComboBox(this)),
      m_options(new QToolButton(this)), m_interval(new QSpinBox(this)),
      m_connect(new QPushButton(tr("Connect"), this)), m_link(new LedIndicator({}, this)),
      m_rate(new QLabel(this)), m_replyWatch(new QTimer(this))
{
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    for (const ModelInfo& model : models())
        m_model->addItem(modelDisplayName(model), model.id);
    m_model->setToolTip(tr("Controller model"));
    // Both combos give way on a narrow screen (issue 11: the bar must fit 1024 px); the
    // popup lists still show the full names.
    m_model->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_model->setMinimumContentsLength(13);
    m_model->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    m_port->setEditable(true);
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumContentsLength(15);
    m_port->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_port->setToolTip(tr("Serial port, the in-process simulator, tcp://HOST:PORT for a serial "
                          "device server, or a device path such as /dev/pts/3"));
    m_port->lineEdit()->setPlaceholderText(tr("port, tcp://host:port or path"));
    m_interval->setRange(10, 2000);
    m_interval->setSuffix(tr(" ms"));
    m_interval->setToolTip(tr("Status poll interval"));
    m_interval->setValue(QSettings().value(QStringLiteral("connection/pollMs"), 50).toInt());
    // Issue 7: the E-LAB manual's text names RTS as the reset line, its DE-9 pin table the
    // DTR pin; the operator picks what the cable wires (the CLI's --reset-line).
    m_resetLine->addItem(tr("RTS"), resetLineName(LineSettings::ResetLine::Rts));
    m_resetLine->addItem(tr("DTR"), resetLineName(LineSettings::ResetLine::Dtr));
    m_resetLine->setToolTip(tr("The modem line wired to the controller's reset input"));
    m_resetLabel->setBuddy(m_resetLine);
    buildOptions();
    m_connect->setMinimumWidth(110);
    m_rate->setToolTip(tr("Achieved status poll rate"));

    layout->addWidget(new QLabel(tr("Model:"), this));
    // The model's name takes most of the room to spare (issue 31: the German names were
    // clipped at 1366 px), a port's path less: it scrolls in its line edit.
    layout->addWidget(m_model, 3);
    layout->addSpacing(8);
    layout->addWidget(new QLabel(tr("Port:"), this));
    layout->addWidget(m_port, 1);
    layout->addWidget(m_options);
    layout->addWidget(m_resetLabel);
    layout->addWidget(m_resetLine);
    layout->addWidget(new QLabel(tr("Poll:"), this));
    layout->addWidget(m_interval);
    layout->addWidget(m_connect);
    layout->addSpacing(8);
    layout->addWidget(m_link);
    layout->addWidget(m_rate);

    fillPorts();
    const QSettings settings;
    setSelectedModel(settings
                         .value(QStringLiteral("connection/model"),
                                models().isEmpty() ? QString() : models().first().id)
                         .toString());
    setPortSpec(settings.value(QStringLiteral("connection/port"), kSim).toString());
    m_context->selectModel(selectedModelId());
    updateResetLine();

    connect(m_scanner, &PortScanner::portsChanged, this, &ConnectionBar::fillPorts);
    connect(m_scanner, &PortScanner::scanned, this, &ConnectionBar::onPortsScanned);
    connect(m_watcher, &PortWatcher::deviceReturned, this, &ConnectionBar::onDeviceReturned);
    connect(m_resetLine, &QComboBox::activated, this, [this] {
        const auto line = resetLineFromName(m_resetLine->currentData().toString());
        connectionsettings::setResetLine(selectedModelId(),
                                         line.value_or(LineSettings::ResetLine::Rts));
    });
    connect(m_connect, &QPushButton::clicked, this, &ConnectionBar::toggleConnection);
    connect(m_port->lineEdit(), &QLineEdit::returnPressed, this, &ConnectionBar::connectNow);
    connect(m_model, &QComboBox::currentIndexChanged, this, [this] {
        m_watcher->forget(); // another model: the old link is not coming back
        m_context->selectModel(selectedModelId());
        updateResetLine();
    });
    connect(m_interval, &QSpinBox::valueChanged, this, [this](int ms) {
        QSettings().setValue(QStringLiteral("connection/pollMs"), ms);
        m_context->session()->setPollInterval(ms);
    });
    ControllerSession* session = m_context->session();
    connect(session, &ControllerSession::linkStateChanged, this, &ConnectionBar::onLinkState);
    connect(session, &ControllerSession::pollRateChanged, this, &ConnectionBar::onPollRate);
    // Any byte from the device is a reply; polls run every few tens of milliseconds.
    connect(session, &ControllerSession::traffic, this, [this](const TrafficRecord& r) {
        if (r.direction != TrafficRecord::Direction::In)
            return;
        // Only the monotonic clock per reply: the wall-clock time is worked out when the
        // message needs it (QTime::currentTime's time-zone conversion, 20 times a second, was
        // a tenth of the idle GUI thread's samples, issue 21).
        m_sinceReply.start();
        if (m_overdue)
            checkReplies();
    });
    m_replyWatch->setInterval(100);
    connect(m_replyWatch, &QTimer::timeout, this, &ConnectionBar::checkReplies);
    onLinkState(LinkState::Disconnected, {});
}

QString ConnectionBar::rateText(double hz)
{
    return tr("%1 Hz").arg(hz, 0, 'f', 1);
}

QString ConnectionBar::portSpec() const
{
    const QString text = m_port->currentText().trimmed();
    const int index = m_port->findText(text);
    if (index >= 0)
        return m_port->itemData(index).toString();
    if (text.compare(kSim, Qt::CaseInsensitive) == 0)
        return kSim;
    return text;
}

void ConnectionBar::setPortSpec(const QString& spec)
{
    const int index = m_port->findData(spec);
    if (index >= 0)
        m_port->setCurrentIndex(index);
    else
        m_port->setEditText(spec);
}

bool ConnectionBar::setPollInterval(int ms)
{
    if (ms < m_interval->minimum() || ms > m_interval->maximum())
        return false;
    m_interval->setValue(ms);
    return true;
}

QString ConnectionBar::selectedModelId() const
{
    return m_model->currentData().toString();
}

void ConnectionBar::setSelectedModel(const QString& modelId)
{
    const int index = m_model->findData(modelId);
    if (index >= 0)
        m_model->setCurrentIndex(index);
}

void ConnectionBar::fillPorts()
{
    // Keep what the operator selected or typed across rescans.
    const QString keep = m_port->count() ? portSpec() : QString();
    const bool typed = !keep.isEmpty() && m_port->findData(keep) < 0;
    const QString typedText = m_port->currentText();
    m_port->blockSignals(true);
    m_port->clear();
    m_port->addItem(tr("Simulator (in-process)"), kSim);
    for (const PortEntry& entry : m_scanner->ports())
        m_port->addItem(entry.label, entry.path);
    // Recent ports the scan cannot list (ptys, tcp://): one click away.
    for (const QString& recent : connectionsettings::recentPorts()) {
        if (m_port->findData(recent) < 0)
            m_port->addItem(recent, recent);
    }
    m_port->blockSignals(false);
    if (typed)
        m_port->setEditText(typedText);
    else if (!keep.isEmpty())
        setPortSpec(keep);
}

void ConnectionBar::toggleConnection()
{
    const LinkState state = m_context->session()->linkState();
    if (m_context->session()->isCreated() &&
        (state == LinkState::Connected || state == LinkState::Connecting))
        disconnectNow();
    else
        connectNow();
}

ConnectionSpec ConnectionBar::currentSpec() const
{
    ConnectionSpec spec;
    spec.port = portSpec();
    spec.options.pollIntervalMs = m_interval->value();
    // The same choice the CLI passes with --reset-line (CliSession).
    spec.options.resetLine = connectionsettings::resetLine(selectedModelId());
    return spec;
}

void ConnectionBar::connectNow()
{
    const ConnectionSpec spec = currentSpec();
    if (spec.port.isEmpty()) {
        Q_EMIT connectionFailed(tr("Choose a port first."));
        return;
    }
    m_watcher->forget(); // the operator chose: follow the device of this link from now on
    m_reconnecting = false;
    connectWith(spec);
}

bool ConnectionBar::connectWith(const ConnectionSpec& spec)
{
    const QString modelId = selectedModelId();
    const ModelInfo* model = findModel(modelId);
    QString error;
    if (!model || !m_context->connectTo(*model, spec, &error)) {
        Q_EMIT connectionFailed(model ? error : unknownModelText(modelId));
        return false;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("connection/model"), model->id);
    settings.setValue(QStringLiteral("connection/port"), spec.port);
    return true;
}

void ConnectionBar::disconnectNow()
{
    m_watcher->forget(); // the operator ended the link: it does not come back by itself
    m_reconnecting = false;
    m_context->disconnectFromController();
}

void ConnectionBar::onLinkState(LinkState state, const QString& reason)
{
    const bool busy = state == LinkState::Connected || state == LinkState::Connecting;
    m_connect->setText(busy ? tr("Disconnect") : tr("Connect"));
    m_model->setEnabled(!busy);
    m_port->setEnabled(!busy);
    m_resetLine->setEnabled(!busy);
    switch (state) {
    case LinkState::Disconnected:
        // A connect that never got through says so (the reason is the tooltip and the
        // status bar message).
        if (m_lastState == LinkState::Connecting && m_reconnecting) {
            m_reconnecting = false;
            m_watcher->reconnectFailed(); // tried again on the next scan that lists it
        }
        if (m_lastState == LinkState::Connecting && !reason.isEmpty())
            showLink(LedIndicator::State::Fault, tr("Connect failed"));
        else
            showLink(LedIndicator::State::Off, tr("Disconnected"));
        break;
    case LinkState::Connecting:
        showLink(LedIndicator::State::Warning, tr("Connecting"));
        break;
    case LinkState::Connected:
        onConnected();
        m_sinceReply.start(); // the link was just confirmed
        m_overdue = false;
        showLink(LedIndicator::State::On, tr("Connected"));
        break;
    case LinkState::Lost:
        showLink(LedIndicator::State::Fault, tr("Link lost"));
        break;
    }
    m_link->setToolTip(reason);
    m_lastState = state;
    // Without a status request (laser motor axes) silence is what a healthy idle link sounds
    // like: no reply watch, and the rate field says why there is none (issue 16).
    const bool polled = m_context->capabilities().statusQuery;
    if (state == LinkState::Connected && polled)
        m_replyWatch->start();
    else
        m_replyWatch->stop();
    // The rate changes every half second while polling: its field keeps one size (room for
    // every text it can show for this model), so a new rate re-lays out nothing (issue 21).
    reserveTextSize(m_rate, polled ? QStringList{tr("\u2013 Hz"), rateText(888.8)}
                                   : QStringList{tr("\u2013 Hz"), tr("no status poll")});
    if (state == LinkState::Connected && !polled) {
        m_rate->setText(tr("no status poll"));
        m_rate->setToolTip(tr("This protocol has no status request: the controller reports only "
                              "by itself (after a move, at a switch or the door). Silence on an "
                              "idle link is normal and is not checked."));
    } else if (!busy) {
        m_rate->setText(tr("\u2013 Hz"));
        m_rate->setToolTip(tr("Achieved status poll rate"));
    }
}

int ConnectionBar::overdueAfterMs() const
{
    return qMax(400, 4 * m_interval->value());
}

void ConnectionBar::checkReplies()
{
    if (!m_context->isConnected() || !m_context->capabilities().statusQuery)
        return;
    const bool overdue = m_sinceReply.isValid() && m_sinceReply.elapsed() > overdueAfterMs();
    if (overdue == m_overdue)
        return;
    m_overdue = overdue;
    if (overdue) {
        const QTime lastReply = QTime::currentTime().addMSecs(-int(m_sinceReply.elapsed()));
        showLink(LedIndicator::State::Warning,
                 tr("No reply since %1").arg(lastReply.toString(QStringLiteral("HH:mm:ss"))));
    } else {
        showLink(LedIndicator::State::On, tr("Connected"));
    }
}

void ConnectionBar::showLink(LedIndicator::State state, const QString& text)
{
    m_link->setState(state);
    m_link->setText(text);
    Q_EMIT linkTextChanged(text, state == LedIndicator::State::Warning ||
                                     state == LedIndicator::State::Fault);
}

QString ConnectionBar::linkText() const
{
    return m_link->text();
}

void ConnectionBar::onPollRate(double hz)
{
    if (!m_context->capabilities().statusQuery)
        return; // nothing is polled: the field keeps saying so
    m_rate->setText(rateText(hz));
}

} // namespace stepdeck::ui
