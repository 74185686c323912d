#include "RawWordView.h"
#include "common/LedIndicator.h"
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>

namespace stepdeck::ui {

RawWordView::RawWordView(const StatusWordInfo& info, QWidget* parent)
    : QGroupBox(info.title, parent), m_info(info), m_title(info.title),
      m_key(new QLabel(tr("Raw %1:").arg(info.key), this)), m_hex(new QLabel(this))
{
    auto* layout = new QGridLayout(this);
    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    mono.setBold(true);
    m_hex->setFont(mono);
    m_hex->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The heading spans the lamp columns: it does not widen the first one.
    auto* heading = new QHBoxLayout;
    heading->addWidget(m_key);
    heading->addWidget(m_hex);
    heading->addStretch(1);
    layout->addLayout(heading, 0, 0, 1, 2);
    m_grid = layout;
    for (const StatusBitInfo& bit : info.bits) {
        auto* lamp = new LedIndicator(bit.name, this);
        lamp->setObjectName(bit.name);
        QString tip =
            QStringLiteral("<b>%1</b> (%2)<br>%3")
                .arg(bit.name, tr("bit %1").arg(bit.bit), bit.description.toHtmlEscaped());
        if (!bit.implemented) {
            tip += QStringLiteral("<br><i>%1</i>")
                       .arg(tr("Not implemented by the firmware: always off."));
            lamp->setEnabled(false);
        }
        lamp->setToolTip(tip);
        m_lamps.append({bit, lamp});
    }
    setColumns(2);
    setValue({});
}

QSize RawWordView::minimumSizeHint() const
{
    const QSize inside = layout()->totalMinimumSize();
    return QSize(inside.width(), QGroupBox::minimumSizeHint().height());
}

void RawWordView::resizeEvent(QResizeEvent* event)
{
    QGroupBox::resizeEvent(event);
    showTitle();
}

void RawWordView::showTitle()
{
    // Room for the title: the frame's width less the space around the title (about 3 em).
    const QString shown =
        fontMetrics().elidedText(m_title, Qt::ElideRight, width() - 3 * fontMetrics().height());
    if (shown != title()) {
        setTitle(shown);
        setToolTip(shown == m_title ? QString() : m_title);
    }
}

void RawWordView::retarget(const QString& key, const QString& title)
{
    if (key == m_info.key && title == m_title)
        return;
    m_info.key = key;
    m_title = title;
    m_key->setText(tr("Raw %1:").arg(key));
    showTitle();
    setValue({});
}

void RawWordView::setColumns(int columns)
{
    columns = qBound(1, columns, 2);
    if (columns == m_columns)
        return;
    m_columns = columns;
    for (const auto& entry : std::as_const(m_lamps))
        m_grid->removeWidget(entry.second);
    for (int i = 0; i < m_lamps.size(); ++i)
        m_grid->addWidget(m_lamps.at(i).second, 1 + i / columns, i % columns);
}

void RawWordView::fitWidth(int room)
{
    int cell = 0;
    for (const auto& entry : std::as_const(m_lamps))
        cell = qMax(cell, entry.second->sizeHint().width());
    const QMargins margins = m_grid->contentsMargins();
    const int inside = room - (width() - contentsRect().width()) - margins.left() - margins.right();
    setColumns(inside >= 2 * cell + m_grid->horizontalSpacing() ? 2 : 1);
}

void RawWordView::setValue(const QVariant& value)
{
    const int digits = (m_info.width + 3) / 4;
    if (!value.isValid()) {
        m_hex->setText(QStringLiteral("0x") + QString(digits, QLatin1Char('-')));
        for (auto& [bit, lamp] : m_lamps)
            lamp->setState(LedIndicator::State::Unknown);
        return;
    }
    const quint64 word = value.toULongLong();
    m_hex->setText(QStringLiteral("0x%1").arg(
        QString::number(word, 16).toUpper().rightJustified(digits, QLatin1Char('0'))));
    for (auto& [bit, lamp] : m_lamps) {
        const bool on = word & (quint64(1) << bit.bit);
        lamp->setOn(on, bit.fault ? LedIndicator::State::Fault : LedIndicator::State::On);
    }
}

QString RawWordView::hexText() const
{
    return m_hex->text();
}

LedIndicator* RawWordView::lamp(const QString& bitName) const
{
    for (const auto& [bit, lamp] : m_lamps) {
        if (bit.name == bitName)
            return lamp;
    }
    return nullptr;
}

} // namespace stepdeck::ui
