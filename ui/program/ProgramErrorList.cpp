#include "ProgramErrorList.h"
#include "ProgramEditor.h"
#include "common/ElidedLabel.h"
#include <QListWidget>
#include <QVBoxLayout>

namespace stepdeck::ui {

namespace {
constexpr int kLineRole = Qt::UserRole;
constexpr int kColumnRole = Qt::UserRole + 1;
} // namespace

ProgramErrorList::ProgramErrorList(ProgramEditor* editor, QWidget* parent)
    : QWidget(parent), m_editor(editor), m_header(new ElidedLabel(this)),
      m_list(new QListWidget(this))
{
    setObjectName(QStringLiteral("programErrorList"));
    m_header->setObjectName(QStringLiteral("programErrorHeader"));
    m_header->setStyleSheet(QStringLiteral("QLabel { color: #b00000; }")); // as the check line
    m_list->setObjectName(QStringLiteral("programErrorEntries"));
    // A long entry wraps (German reasons run to twice the list's width) instead of scrolling
    // sideways; the tooltip still has it whole.
    m_list->setWordWrap(true);
    m_list->setResizeMode(QListView::Adjust);
    m_list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // As small as the preview's other tabs may get (issue 47 item 12: the list is one of them),
    // so that it does not make the page taller than a bottom dock on a 768-pixel screen.
    m_list->setMinimumSize(120, 40);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(m_header);
    v->addWidget(m_list, 1);
    // A click, or Enter (activated) on the entry with the keyboard's focus.
    connect(m_list, &QListWidget::itemClicked, this, &ProgramErrorList::goTo);
    connect(m_list, &QListWidget::itemActivated, this, &ProgramErrorList::goTo);
    setErrors({});
}

void ProgramErrorList::setErrors(const QList<program::ProgramError>& errors)
{
    m_list->clear();
    for (const program::ProgramError& e : errors) {
        // An error of no line (the program as a whole): its message alone.
        const QString text = e.line > 0 ? tr("line %1: %2").arg(e.line).arg(e.message) : e.message;
        auto* item = new QListWidgetItem(text, m_list);
        item->setData(kLineRole, e.line);
        item->setData(kColumnRole, e.column);
        item->setToolTip(item->text());
    }
    m_header->setText(errors.isEmpty() ? tr("No errors.")
                                       : tr("%n error(s); click one to go to its line.", nullptr,
                                            int(errors.size())));
    if (m_list->count() > 0)
        m_list->setCurrentRow(0);
}

int ProgramErrorList::errorCount() const
{
    return m_list->count();
}

QString ProgramErrorList::headerText() const
{
    return m_header->text();
}

void ProgramErrorList::goTo(const QListWidgetItem* item)
{
    if (!item)
        return;
    const int line = item->data(kLineRole).toInt();
    if (line < 1 || m_editor->goToLine(line, item->data(kColumnRole).toInt()))
        return;
    // A file too large to edit shows its first lines only (ProgramFiles): say so rather than
    // doing nothing.
    m_header->setText(tr("Line %1 is not in the editor, which shows the first %n line(s) of "
                         "this large file.",
                         nullptr, m_editor->document()->blockCount())
                          .arg(line));
}

} // namespace stepdeck::ui
