#include "RawWordView.h"
#include "common/LedIndicator.h"
#include <QGridLayout>
#include <QLabel>

namespace stepdeck::ui {

RawWordView::RawWordView(const StatusWordInfo& info, QWidget* parent)
    : QGroupBox(info.title, parent), m_info(info), m_hex(new QLabel(this))
{
    auto* layout = new QGridLayout(this);
    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    mono.setBold(true);
    m_hex->setFont(mono);
    m_hex->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(new QLabel(tr("Raw %1:").arg(info.key), this), 0, 0);
    layout->addWidget(m_hex, 0, 1);
    const int columns = 2;
    int i = 0;
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
        layout->addWidget(lamp, 1 + i / columns, i % columns);
        m_lamps.append({bit, lamp});
        ++i;
    }
    setValue({});
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
