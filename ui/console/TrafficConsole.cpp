#include "TrafficConsole.h"
#include "common/ConnectionGate.h"
#include "common/Dialogs.h"
#include "common/ElidedLabel.h"
#include "machine/MachineContext.h"
#include <QCheckBox>
#include <QFile>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QTextBlock>
#include <QTimer>

namespace stepdeck::ui {

namespace {
const QColor kOutColour(0x15, 0x65, 0xc0);
const QColor kInColour(0x2e, 0x7d, 0x32);
} // namespace

TrafficConsole::TrafficConsole(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_view(new QPlainTextEdit(this)),
      m_hex(new QCheckBox(tr("Hex"), this)), m_hidePolls(new QCheckBox(tr("Hide polls"), this)),
      m_pause(new QCheckBox(tr("Pause"), this)), m_send(new QLineEdit(this)),
      m_sendButton(new QPushButton(tr("Send"), this)), m_sendError(new ElidedLabel(this, 2)),
      m_count(new QLabel(this)), m_refresh(new QTimer(this))
{
    auto* clearButton = new QPushButton(tr("Clear"), this);
    auto* save = new QPushButton(tr("Save\u2026"), this);
    m_hidePolls->setChecked(true);
    m_hidePolls->setToolTip(tr("Hide the status poller's requests and replies"));
    m_pause->setToolTip(tr("Freeze the view; traffic is still recorded"));
    auto* bar = new QHBoxLayout;
    for (QWidget* w : std::initializer_list<QWidget*>{m_hex, m_hidePolls, m_pause})
        bar->addWidget(w);
    bar->addStretch(1);
    bar->addWidget(m_count);
    bar->addWidget(clearButton);
    bar->addWidget(save);

    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    m_view->setFont(mono);
    m_view->setReadOnly(true);
    m_view->setMaximumBlockCount(5000);
    m_view->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_view->setObjectName(QStringLiteral("trafficView"));
    m_send->setFont(mono);
    m_send->setObjectName(QStringLiteral("trafficSend"));
    updateSendHint();
    connect(context, &MachineContext::modelChanged, this, &TrafficConsole::updateSendHint);
    m_send->setClearButtonEnabled(true);
    m_sendError->setStyleSheet(QStringLiteral("QLabel { color: #c62828; }"));
    // Two lines reserved, a longer error elided (full text in the tooltip): the send field
    // above never moves while the operator types (issue 16).
    m_sendError->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);

    auto* sendRow = new QHBoxLayout;
    sendRow->addWidget(m_send, 1);
    sendRow->addWidget(m_sendButton);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_view, 1);
    layout->addLayout(sendRow);
    layout->addWidget(m_sendError);

    // Batch appends: polls arrive at up to 100 records per second. The refresh runs only while
    // the console is on screen (updateRefresh); behind another tab it would re-lay out the
    // record count ten times a second for nobody (issue 21, idle cost).
    m_refresh->setInterval(100);
    connect(m_refresh, &QTimer::timeout, this, &TrafficConsole::flush);
    connect(m_hex, &QCheckBox::toggled, this, &TrafficConsole::rerender);
    connect(m_hidePolls, &QCheckBox::toggled, this, &TrafficConsole::rerender);
    connect(m_pause, &QCheckBox::toggled, this, [this](bool paused) {
        if (!paused)
            rerender();
    });
    connect(clearButton, &QPushButton::clicked, this, &TrafficConsole::clear);
    connect(save, &QPushButton::clicked, this, &TrafficConsole::saveAs);
    auto* gate = new ConnectionGate(context, this); // raw bytes need a connection
    gate->add(m_send);
    gate->add(m_sendButton);
    connect(m_send, &QLineEdit::returnPressed, this, &TrafficConsole::sendCurrentLine);
    connect(m_sendButton, &QPushButton::clicked, this, &TrafficConsole::sendCurrentLine);
    connect(m_send, &QLineEdit::textEdited, m_sendError, &QLabel::clear);
    connect(context->session(), &ControllerSession::traffic, this, &TrafficConsole::append);
    connect(context->session(), &ControllerSession::requestFinished, this,
            &TrafficConsole::onResult);
}

void TrafficConsole::updateSendHint()
{
    // In the connected model's own notation (ModelPresentation::trafficExample).
    const ModelInfo* model = m_context->model();
    m_send->setPlaceholderText(model && model->presentation.trafficExample
                                   ? model->presentation.trafficExample()
                                   : tr("Send raw bytes: text as it is, \\r for CR, <xNN> for "
                                        "any other byte."));
}

QString TrafficConsole::formatBytes(const QByteArray& bytes) const
{
    if (m_hex->isChecked())
        return QString::fromLatin1(bytes.toHex(' ').toUpper());
    const ModelInfo* model = m_context->model();
    if (model && model->presentation.formatTraffic)
        return model->presentation.formatTraffic(bytes);
    return genericFormatTraffic(bytes);
}

bool TrafficConsole::parseLine(const QString& text, QByteArray* bytes, QString* error) const
{
    const ModelInfo* model = m_context->model();
    if (model && model->presentation.parseTraffic)
        return model->presentation.parseTraffic(text, bytes, error);
    return genericParseTraffic(text, bytes, error);
}

QString TrafficConsole::format(const TrafficRecord& record) const
{
    const bool out = record.direction == TrafficRecord::Direction::Out;
    return QStringLiteral("%1  %2  %3")
        .arg(record.timestampUs / 1e6, 12, 'f', 6)
        .arg(out ? QStringLiteral("\u2192") : QStringLiteral("\u2190"))
        .arg(formatBytes(record.bytes));
}

bool TrafficConsole::accepted(const TrafficRecord& record) const
{
    return !(m_hidePolls->isChecked() && record.poll);
}

void TrafficConsole::append(const TrafficRecord& record)
{
    m_records.append(record);
    if (m_records.size() > kMaxRecords)
        m_records.remove(0, m_records.size() - kMaxRecords);
    if (accepted(record)) {
        m_pending.append(record);
        // The view keeps its newest maximumBlockCount() lines: while it is hidden or paused
        // nothing older than those can appear, so nothing more is kept for it.
        const qsizetype keep = m_view->maximumBlockCount();
        if (keep > 0 && m_pending.size() > keep)
            m_pending.remove(0, m_pending.size() - keep);
    }
}

bool TrafficConsole::isRefreshing() const
{
    return m_refresh->isActive();
}

void TrafficConsole::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    updateRefresh();
}

void TrafficConsole::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    updateRefresh();
}

void TrafficConsole::setOnScreen(bool onScreen)
{
    m_onScreen = onScreen;
    updateRefresh();
}

void TrafficConsole::updateRefresh()
{
    // A dock behind another tab stays "visible" (it is only moved off screen): the main
    // window says whether its tab is on top (setOnScreen).
    const bool shown = isVisible() && m_onScreen;
    if (shown == m_refresh->isActive())
        return;
    if (shown) {
        flush(); // what arrived meanwhile appears at once
        m_refresh->start();
    } else {
        m_refresh->stop();
    }
}

void TrafficConsole::flush()
{
    m_count->setText(tr("%n record(s)", nullptr, int(m_records.size())));
    if (m_pause->isChecked() || m_pending.isEmpty())
        return;
    appendToView(m_pending);
    m_pending.clear();
}

void TrafficConsole::appendToView(const QList<TrafficRecord>& records)
{
    QScrollBar* scroll = m_view->verticalScrollBar();
    const bool atEnd = scroll->value() >= scroll->maximum() - 4;
    QTextCursor cursor(m_view->document());
    cursor.movePosition(QTextCursor::End);
    cursor.beginEditBlock();
    QTextCharFormat outFormat;
    outFormat.setForeground(kOutColour);
    QTextCharFormat inFormat;
    inFormat.setForeground(kInColour);
    for (const TrafficRecord& r : records) {
        if (!m_view->document()->isEmpty())
            cursor.insertBlock();
        cursor.insertText(format(r),
                          r.direction == TrafficRecord::Direction::Out ? outFormat : inFormat);
    }
    cursor.endEditBlock();
    if (atEnd)
        scroll->setValue(scroll->maximum());
}

void TrafficConsole::rerender()
{
    m_view->clear();
    m_pending.clear();
    QList<TrafficRecord> shown;
    for (const TrafficRecord& r : std::as_const(m_records)) {
        if (accepted(r))
            shown.append(r);
    }
    if (shown.size() > m_view->maximumBlockCount())
        shown = shown.mid(shown.size() - m_view->maximumBlockCount());
    appendToView(shown);
}

QString TrafficConsole::visibleText() const
{
    return m_view->toPlainText();
}

void TrafficConsole::clear()
{
    m_records.clear();
    m_pending.clear();
    m_view->clear();
    flush();
}

bool TrafficConsole::sendCurrentLine()
{
    const QString text = m_send->text().trimmed();
    if (text.isEmpty())
        return false;
    QByteArray bytes;
    QString error;
    if (!parseLine(text, &bytes, &error)) {
        m_sendError->setText(tr("Not sent: %1").arg(error));
        return false;
    }
    if (!m_context->isConnected()) {
        m_sendError->setText(tr("Not sent: not connected"));
        return false;
    }
    m_sendError->clear();
    m_pendingSend = m_context->session()->sendRaw(bytes);
    m_send->selectAll();
    return true;
}

void TrafficConsole::onResult(const CommandResult& result)
{
    if (result.id != m_pendingSend || m_pendingSend == 0)
        return;
    m_pendingSend = 0;
    if (!result.ok())
        m_sendError->setText(tr("Send failed: %1").arg(result.message));
}

bool TrafficConsole::saveToFile(const QString& path, QString* error) const
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    for (const TrafficRecord& r : m_records) {
        if (accepted(r))
            file.write(format(r).toUtf8() + '\n');
    }
    return true;
}

void TrafficConsole::saveAs()
{
    dialogs::saveFile(this, QStringLiteral("traffic"), tr("Save traffic"),
                      QStringLiteral("traffic.log"), tr("Log files (*.log *.txt)"),
                      [this](const QString& path) {
                          QString error;
                          if (!saveToFile(path, &error))
                              m_sendError->setText(error);
                      });
}

} // namespace stepdeck::ui
