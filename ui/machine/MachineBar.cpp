#include "MachineBar.h"
#include "common/ElidedLabel.h"
#include "common/LayoutItems.h"
#include "common/LedIndicator.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace stepdeck::ui {

MachineBar::MachineBar(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_name(new ElidedLabel(this)), m_lamps(new QHBoxLayout),
      m_controllerLabel(new QLabel(tr("Pages show:"), this)), m_controllers(new QComboBox(this)),
      m_connect(new QPushButton(this))
{
    setObjectName(QStringLiteral("machineBar"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    QFont bold = m_name->font();
    bold.setBold(true);
    m_name->setFont(bold);
    m_controllers->setToolTip(tr("The controller whose setup, records, traffic, drives and "
                                 "charts the pages show"));
    m_controllers->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_controllerLabel->setBuddy(m_controllers);
    m_connect->setMinimumWidth(130);
    m_connect->setToolTip(tr("Connect or disconnect every controller of the machine"));
    layout->addWidget(new QLabel(tr("Machine:"), this));
    // The name takes the room the bar has (up to its whole text), elided below that (issue 31:
    // it was cut at a fixed width even at 1920 px).
    layout->addWidget(m_name, 1);
    layout->addSpacing(8);
    layout->addLayout(m_lamps);
    layout->addStretch(1);
    layout->addWidget(m_controllerLabel);
    layout->addWidget(m_controllers);
    layout->addWidget(m_connect);
    connect(m_connect, &QPushButton::clicked, this, &MachineBar::toggleConnection);
    connect(m_controllers, &QComboBox::activated, this,
            [this] { m_context->selectController(m_controllers->currentData().toString()); });
    connect(context, &MachineContext::machineChanged, this, &MachineBar::rebuild);
    rebuild();
}

void MachineBar::setSingleControllerBar(QWidget* singleController)
{
    m_singleBar = singleController;
    rebuild();
}

void MachineBar::rebuild()
{
    deleteLayoutItems(m_lamps);
    m_entries.clear();
    m_controllers->clear();
    // A machine file's bar, or the connection bar for the connection machine (issue 28,
    // item 0); never both: a hidden one takes no room in the tool bar (the window's minimum
    // width stays what the shown bar needs: tst_windowfit at 1024x768).
    const machine::Machine* m = m_context->isConnectionMachine() ? nullptr : m_context->machine();
    if (m_singleBar)
        m_singleBar->setVisible(!m);
    setVisible(m);
    if (!m)
        return;
    // Long names and ports (a /dev/serial/by-id/... path, a tcp:// address) are elided in the
    // middle to a fixed width, the full text in the tooltip: the tool bar must not grow past
    // the window's width with a machine of several controllers.
    const QFontMetrics metrics = fontMetrics();
    const int nameWidth = metrics.horizontalAdvance(QLatin1Char('M')) * kNameChars;
    const int portWidth = metrics.horizontalAdvance(QLatin1Char('M')) * kPortChars;
    m_name->setMinimumTextWidth(nameWidth);
    m_name->setText(m->description().name);
    const QFontMetrics bold = m_name->fontMetrics();
    m_name->setMaximumWidth(bold.horizontalAdvance(m->description().name) +
                            bold.horizontalAdvance(QLatin1Char(' ')));
    for (const machine::MachineController& c : m->description().controllers) {
        ControllerSession* session = m->session(c.id);
        const QString port = c.isSimulated() ? tr("simulator") : c.port;
        const QString shown = metrics.elidedText(port, Qt::ElideMiddle, portWidth);
        Entry entry{c.id, port, new LedIndicator(tr("%1 @ %2").arg(c.id, shown), this)};
        m_lamps->addWidget(entry.lamp);
        m_controllers->addItem(c.id, c.id);
        // The lamp follows its own controller's link, whichever the pages show.
        connect(session, &ControllerSession::linkStateChanged, entry.lamp,
                [this, entry](LinkState state, const QString& reason) {
                    showLink(entry, state, reason);
                    updateButton();
                });
        showLink(entry, session->linkState(), {});
        m_entries << entry;
    }
    m_controllers->setCurrentIndex(m_controllers->findData(m_context->selectedController()));
    const bool several = m->description().controllers.size() > 1;
    m_controllerLabel->setVisible(several);
    m_controllers->setVisible(several);
    updateButton();
}

void MachineBar::showLink(const Entry& entry, LinkState state, const QString& reason)
{
    using State = LedIndicator::State;
    State lamp = State::Off;
    QString text = tr("Disconnected");
    switch (state) {
    case LinkState::Disconnected:
        break;
    case LinkState::Connecting:
        lamp = State::Warning;
        text = tr("Connecting");
        break;
    case LinkState::Connected:
        lamp = State::On;
        text = tr("Connected");
        break;
    case LinkState::Lost:
        lamp = State::Fault;
        text = tr("Link lost");
        break;
    }
    entry.lamp->setState(lamp);
    const QString who = tr("%1 @ %2").arg(entry.id, entry.port);
    entry.lamp->setToolTip(reason.isEmpty() ? tr("%1: %2").arg(who, text)
                                            : tr("%1: %2 (%3)").arg(who, text, reason));
}

void MachineBar::updateButton()
{
    m_connect->setText(m_context->machineLinkBusy() ? tr("Disconnect all") : tr("Connect all"));
}

void MachineBar::toggleConnection()
{
    if (m_context->machineLinkBusy())
        m_context->disconnectMachine();
    else
        m_context->connectMachine();
}

LedIndicator* MachineBar::lamp(const QString& controllerId) const
{
    for (const Entry& e : m_entries) {
        if (e.id == controllerId)
            return e.lamp;
    }
    return nullptr;
}

QString MachineBar::lampText(const QString& controllerId) const
{
    const LedIndicator* l = lamp(controllerId);
    return l ? l->toolTip() : QString();
}

} // namespace stepdeck::ui
