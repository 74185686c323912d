#include "SetupDriveChooser.h"
#include "machine/MachineContext.h"
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>

namespace stepdeck::ui {

SetupDriveChooser::SetupDriveChooser(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_edit(new QLineEdit(this)), m_label(new QLabel(this))
{
    m_edit->setObjectName(QStringLiteral("setupDriveFilter"));
    m_edit->setPlaceholderText(tr("Drives: name or address"));
    m_edit->setClearButtonEnabled(true);
    m_edit->setToolTip(tr("The setup shows the first %1 drives whose name or bus address "
                          "contains this text.")
                           .arg(kColumns));
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The label's text changes with the choice; it takes the rest of the row, elided by
    // nothing around it, so the groups below never move.
    m_label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(new QLabel(tr("Drives shown:"), this));
    h->addWidget(m_edit);
    h->addWidget(m_label, 1);
    connect(m_edit, &QLineEdit::textChanged, this, &SetupDriveChooser::onText);
}

QList<Axis> SetupDriveChooser::choose(const QList<Axis>& axes, const QStringList& names,
                                      const QList<int>& addresses, const QString& text)
{
    QList<Axis> out;
    const QString wanted = text.trimmed();
    for (int i = 0; i < axes.size() && out.size() < kColumns; ++i) {
        const QString address =
            addresses.value(i) > 0 ? QString::number(addresses.at(i)) : QString();
        if (wanted.isEmpty() || names.value(i).contains(wanted, Qt::CaseInsensitive) ||
            address.contains(wanted))
            out << axes.at(i);
    }
    return out;
}

void SetupDriveChooser::setAxes(const QList<Axis>& axes)
{
    m_axes = axes;
    const QSignalBlocker block(m_edit);
    m_edit->clear();
    m_shownFor.clear();
    m_shown = axes.mid(0, kColumns);
    showChoice();
}

void SetupDriveChooser::onText(const QString& text)
{
    QStringList names;
    QList<int> addresses;
    const QMap<Axis, int> bus = m_context->session()->spec().options.axisAddresses;
    for (Axis a : std::as_const(m_axes)) {
        names << m_context->controllerAxisName(a);
        addresses << bus.value(a, 0);
    }
    const QList<Axis> chosen = choose(m_axes, names, addresses, text);
    if (chosen.isEmpty()) {
        m_label->setText(tr("No drive matches \u201c%1\u201d; still shown: %2")
                             .arg(text.trimmed(), shownText()));
        return; // the columns stay: an empty page would show nothing to set
    }
    if (chosen == m_shown) {
        m_shownFor = text;
        showChoice();
        return;
    }
    m_before = {m_shown, m_shownFor};
    m_shown = chosen;
    m_shownFor = text;
    showChoice();
    Q_EMIT shownAxesChanged(m_shown);
}

void SetupDriveChooser::revert()
{
    // The page kept its columns: the choice, the text and the label go back to them.
    m_shown = m_before.first;
    m_shownFor = m_before.second;
    const QSignalBlocker block(m_edit);
    m_edit->setText(m_shownFor);
    showChoice();
}

QString SetupDriveChooser::shownText() const
{
    QStringList names;
    for (Axis a : m_shown)
        names << m_context->controllerAxisName(a);
    return names.join(QStringLiteral(", "));
}

void SetupDriveChooser::showChoice()
{
    m_label->setText(
        tr("%1 (%2 of %3 drives)").arg(shownText()).arg(m_shown.size()).arg(m_axes.size()));
}

} // namespace stepdeck::ui
