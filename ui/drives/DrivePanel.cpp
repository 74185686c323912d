#include "DrivePanel.h"
#include "ClosedLoopPanel.h"
#include "common/AxisListBar.h"
#include "common/AxisRowFilter.h"
#include "common/ElidedLabel.h"
#include "drives/DriveListModel.h"
#include "drives/PositionErrorResetButton.h"
#include "machine/MachineContext.h"
#include "model/ModelOperations.h"
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableView>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

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
    : QWidget(parent), m_context(context), m_drives(new QTableView(this)),
      m_driveModel(new DriveListModel(this)), m_driveFilter(new AxisRowFilter(this)),
      m_found(makeTable({tr("Address"), tr("Hardware"), tr("Firmware"), tr("Date")}, this)),
      m_closedLoop(new ClosedLoopPanel(context, this)),
      m_scan(new QPushButton(tr("Scan bus"), this)),
      m_cancelScan(new QPushButton(tr("Cancel"), this)), m_progress(new QProgressBar(this)),
      m_scanState(new ElidedLabel(this, 2))
{
    m_drives->setObjectName(QStringLiteral("driveTable"));
    m_found->setObjectName(QStringLiteral("foundTable"));
    m_scan->setObjectName(QStringLiteral("scanBusButton"));
    showAddressRange();
    auto* v = new QVBoxLayout(this);
    v->addWidget(new QLabel(tr("Drives of this machine"), this));
    // A bus of up to 254 drives (issue 32, step 5): filtered by name or address; moving ones
    // first only on request, so a row the operator is about to pick does not jump away.
    m_driveFilter->setSourceModel(m_driveModel);
    m_drives->setModel(m_driveFilter);
    m_drives->verticalHeader()->hide();
    m_drives->horizontalHeader()->setStretchLastSection(true);
    m_drives->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_drives->setEditTriggers(QAbstractItemView::NoEditTriggers);
    // At least four drives in view: in a short dock the page scrolls, the list is not squeezed.
    m_drives->setMinimumHeight(m_drives->horizontalHeader()->sizeHint().height() +
                               4 * m_drives->verticalHeader()->defaultSectionSize() +
                               2 * m_drives->frameWidth());
    m_driveBar = new AxisListBar(m_driveFilter, this);
    v->addWidget(m_driveBar);
    v->addWidget(m_drives, 2);
    // Named by the core's position-error messages (ControllerOptions::actionNames).
    m_resetError = new PositionErrorResetButton(context, m_drives, this);
    auto* driveActions = new QHBoxLayout;
    driveActions->addWidget(m_resetError);
    driveActions->addStretch(1);
    v->addLayout(driveActions);
    v->addWidget(m_closedLoop);
    connect(m_resetError, &PositionErrorResetButton::message, this,
            [this](const QString& text) { m_scanState->setText(text); });
    auto* row = new QHBoxLayout;
    row->addWidget(m_scan);
    row->addWidget(m_cancelScan);
    row->addWidget(m_progress, 1);
    m_cancelScan->setObjectName(QStringLiteral("cancelScanButton"));
    m_cancelScan->setToolTip(tr("Stop the scan after the addresses being asked now"));
    m_progress->setTextVisible(true);
    m_progress->setValue(0);
    // Two lines reserved (full text in the tooltip): the found list below never moves.
    m_scanState->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    v->addLayout(row);
    v->addWidget(m_scanState);
    v->addWidget(m_found, 1);

    ControllerSession* session = m_context->session();
    connect(session, &ControllerSession::statusChanged, this, &DrivePanel::onStatus);
    connect(session, &ControllerSession::requestFinished, this, &DrivePanel::onResult);
    connect(session, &ControllerSession::linkStateChanged, this, &DrivePanel::onLinkState);
    connect(m_context, &MachineContext::modelChanged, this, &DrivePanel::showAddressRange);
    connect(m_scan, &QPushButton::clicked, this, &DrivePanel::scanBus);
    connect(m_cancelScan, &QPushButton::clicked, this, &DrivePanel::cancelScan);
    updateEnabled();
}

QString DrivePanel::scanState() const
{
    return m_scanState->text();
}

void DrivePanel::showAddressRange()
{
    const Capabilities caps = m_context->capabilities();
    m_scan->setToolTip(tr("Ask every address %1..%2 for its firmware (a few seconds); the "
                          "drives of this machine keep their status meanwhile")
                           .arg(caps.minBusAddress)
                           .arg(caps.maxBusAddress));
}

void DrivePanel::scanBus()
{
    const Capabilities caps = m_context->capabilities();
    scanRange(caps.minBusAddress, caps.maxBusAddress);
}

void DrivePanel::scanRange(int first, int last)
{
    if (!m_context->isConnected() || m_scanId)
        return;
    m_found->setRowCount(0);
    m_foundDrives.clear();
    m_scanFirst = first;
    m_scanNext = first;
    m_scanLast = last;
    m_scanCancelled = false;
    m_progress->setRange(first - 1, last);
    m_progress->setValue(first - 1);
    scanNextChunk();
}

void DrivePanel::scanNextChunk()
{
    const int last = qMin(m_scanLast, m_scanNext + kScanChunk - 1);
    m_scanState->setText(tr("Scanning addresses %1..%2 (%3..%4 now)\u2026")
                             .arg(m_scanFirst)
                             .arg(m_scanLast)
                             .arg(m_scanNext)
                             .arg(last));
    m_scanId = m_context->session()->modelOperation(
        operation::kScan, {{operation::arg::kFirst, m_scanNext}, {operation::arg::kLast, last}});
    m_scanNext = last + 1;
    updateEnabled();
}

void DrivePanel::cancelScan()
{
    if (m_scanId)
        m_scanCancelled = true; // takes effect when the chunk in flight answers
}

void DrivePanel::endScan(const QString& text)
{
    m_scanId = 0;
    m_scanState->setText(text);
    updateEnabled();
}

void DrivePanel::onResult(const CommandResult& result)
{
    if (result.id != m_scanId || !m_scanId)
        return;
    if (!result.ok()) {
        endScan(tr("Scan failed: %1").arg(result.message));
        return;
    }
    m_foundDrives += result.value.toList();
    showFound(m_foundDrives);
    m_progress->setValue(m_scanNext - 1);
    if (m_scanCancelled) {
        endScan(tr("Scan cancelled after address %1: %n drive(s) found", nullptr,
                   int(m_foundDrives.size()))
                    .arg(m_scanNext - 1));
        return;
    }
    if (m_scanNext > m_scanLast) {
        endScan(tr("%n drive(s) found", nullptr, int(m_foundDrives.size())));
        return;
    }
    scanNextChunk();
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
}

void DrivePanel::onStatus(const MachineStatus& status)
{
    if (!m_context->isConnected())
        return; // a last status queued behind the disconnect
    QList<DriveListModel::Row> rows;
    rows.reserve(status.drives.size());
    int silent = 0;
    for (const DriveStatus& d : status.drives) {
        DriveListModel::Row row{d, {}, false};
        QStringList axes;
        for (Axis a : d.axes) {
            axes << m_context->controllerAxisName(a);
            const AxisStatus as = status.axes.value(a);
            row.moving = row.moving || as.moving || as.jogging;
        }
        row.axisNames = axes.join(QLatin1Char(','));
        silent += d.responding ? 0 : 1;
        rows << row;
    }
    m_silent = silent;
    // Every poll brings the drives; only what changed is signalled, and the column widths
    // (which lay out every header and cell text) follow a new set of drives only (issue 21).
    const int before = m_driveModel->rowCount();
    if (m_driveModel->setRows(rows) && before != m_driveModel->rowCount())
        m_drives->resizeColumnsToContents();
}

void DrivePanel::onLinkState(LinkState state)
{
    // Without a link the last answers say nothing about the drives any more.
    if (state == LinkState::Disconnected) {
        m_driveModel->setRows({});
        m_silent = 0;
    }
    updateEnabled();
}

void DrivePanel::updateEnabled()
{
    m_scan->setEnabled(m_context->isConnected() && !m_scanId);
    m_cancelScan->setEnabled(m_scanId != 0);
}

} // namespace stepdeck::ui
