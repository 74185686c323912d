#include "DrivePanel.h"
#include "main/MachineContext.h"
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepdeck::ui {

namespace {
QTableWidgetItem* cell(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}

QTableWidget* makeTable(const QStringList& headers, QWidget* parent)
{
    auto* table = new QTableWidget(0, int(headers.size()), parent);
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->hide();
    table->horizontalHeader()->setStretchLastSection(true);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    return table;
}
} // namespace

DrivePanel::DrivePanel(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context),
      m_drives(makeTable({tr("Address"), tr("Axes"), tr("Responding"), tr("Firmware"), tr("State")},
                         this)),
      m_found(makeTable({tr("Address"), tr("Hardware"), tr("Firmware"), tr("Date")}, this)),
      m_scan(new QPushButton(tr("Scan bus"), this)), m_scanState(new QLabel(this))
{
    m_drives->setObjectName(QStringLiteral("driveTable"));
    m_found->setObjectName(QStringLiteral("foundTable"));
    m_scan->setObjectName(QStringLiteral("scanBusButton"));
    m_scan->setToolTip(tr("Ask every address 1..254 for its firmware (a few seconds); the "
                          "drives of this machine keep their status meanwhile"));
    auto* v = new QVBoxLayout(this);
    v->addWidget(new QLabel(tr("Drives of this machine"), this));
    v->addWidget(m_drives, 2);
    auto* row = new QHBoxLayout;
    row->addWidget(m_scan);
    row->addWidget(m_scanState, 1);
    v->addLayout(row);
    v->addWidget(m_found, 1);

    ControllerSession* session = m_context->session();
    connect(session, &ControllerSession::statusChanged, this, &DrivePanel::onStatus);
    connect(session, &ControllerSession::requestFinished, this, &DrivePanel::onResult);
    connect(session, &ControllerSession::linkStateChanged, this, &DrivePanel::onLinkState);
    connect(m_scan, &QPushButton::clicked, this, &DrivePanel::scanBus);
    updateEnabled();
}

QString DrivePanel::scanState() const
{
    return m_scanState->text();
}

void DrivePanel::scanBus()
{
    if (!m_context->isConnected() || m_scanId)
        return;
    m_found->setRowCount(0);
    m_scanState->setText(tr("Scanning addresses 1..254\u2026"));
    m_scanId = m_context->session()->scanBus();
    updateEnabled();
}

void DrivePanel::scanRange(int first, int last)
{
    if (!m_context->isConnected() || m_scanId)
        return;
    m_found->setRowCount(0);
    m_scanState->setText(tr("Scanning addresses %1..%2\u2026").arg(first).arg(last));
    m_scanId = m_context->session()->modelOperation(QStringLiteral("scan"),
                                                    {{"first", first}, {"last", last}});
    updateEnabled();
}

void DrivePanel::onResult(const CommandResult& result)
{
    if (result.id != m_scanId || !m_scanId)
        return;
    m_scanId = 0;
    if (result.ok())
        showFound(result.value.toList());
    else
        m_scanState->setText(tr("Scan failed: %1").arg(result.message));
    updateEnabled();
}

void DrivePanel::showFound(const QVariantList& drives)
{
    m_found->setRowCount(int(drives.size()));
    for (int r = 0; r < drives.size(); ++r) {
        const QVariantMap d = drives.at(r).toMap();
        m_found->setItem(r, FoundAddress, cell(d.value(QStringLiteral("address")).toString()));
        m_found->setItem(r, FoundHardware, cell(d.value(QStringLiteral("hardware")).toString()));
        m_found->setItem(r, FoundFirmware, cell(d.value(QStringLiteral("firmware")).toString()));
        m_found->setItem(r, FoundDate, cell(d.value(QStringLiteral("date")).toString()));
    }
    m_scanState->setText(tr("%n drive(s) found", nullptr, int(drives.size())));
}

void DrivePanel::onStatus(const MachineStatus& status)
{
    if (!m_context->isConnected())
        return; // a last status queued behind the disconnect
    m_drives->setRowCount(int(status.drives.size()));
    m_silent = 0;
    for (int r = 0; r < status.drives.size(); ++r) {
        const DriveStatus& d = status.drives.at(r);
        QStringList axes;
        for (Axis a : d.axes)
            axes << axisName(a);
        m_drives->setItem(r, Address, cell(QString::number(d.address)));
        m_drives->setItem(r, Axes, cell(axes.join(QLatin1Char(','))));
        // A silent drive must stand out at a glance: red cell, cross mark, capitals.
        QTableWidgetItem* answer =
            cell(d.responding ? tr("\u2714 yes") : tr("\u2716 NOT RESPONDING"));
        if (!d.responding) {
            answer->setBackground(QColor(0xc6, 0x28, 0x28));
            answer->setForeground(Qt::white);
            answer->setToolTip(tr("The drive stopped answering; check its power, address and "
                                  "the RS485 wiring. The other drives keep working."));
            ++m_silent;
        }
        m_drives->setItem(r, Responding, answer);
        m_drives->setItem(r, Firmware, cell(d.firmware));
        m_drives->setItem(r, Detail, cell(d.detail));
    }
    m_drives->resizeColumnsToContents();
}

void DrivePanel::onLinkState(LinkState state)
{
    // Without a link the last answers say nothing about the drives any more.
    if (state == LinkState::Disconnected) {
        m_drives->setRowCount(0);
        m_silent = 0;
    }
    updateEnabled();
}

void DrivePanel::updateEnabled()
{
    m_scan->setEnabled(m_context->isConnected() && !m_scanId);
}

} // namespace stepdeck::ui
