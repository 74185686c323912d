#include "AxisStatusList.h"
#include "common/AxisListBar.h"
#include "common/AxisRowFilter.h"
#include "machine/MachineContext.h"
#include "status/AxisStatusModel.h"
#include "status/RawWordView.h"
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QTableView>
#include <QVBoxLayout>

namespace stepdeck::ui {

namespace {
// The word of kind `kind` (the model's title of it) that `axis` has.
std::optional<StatusWordInfo> wordOf(const QList<StatusWordInfo>& words, const QString& kind,
                                     Axis axis)
{
    for (const StatusWordInfo& w : words) {
        if (w.axis == axis && w.title == kind)
            return w;
    }
    return std::nullopt;
}
} // namespace

AxisStatusList::AxisStatusList(MachineContext* context, const QList<StatusWordInfo>& axisWords,
                               QWidget* parent)
    : QGroupBox(tr("Axes"), parent), m_context(context), m_model(new AxisStatusModel(this)),
      m_filter(new AxisRowFilter(this)), m_view(new QTableView(this)), m_axisWords(axisWords)
{
    setObjectName(QStringLiteral("axisStatusList"));
    QList<AxisStatusModel::Row> rows;
    for (Axis axis : context->axes())
        rows.append({axis, context->controllerAxisName(axis)});
    m_model->setRows(rows);
    m_filter->setSourceModel(m_model);
    m_bar = new AxisListBar(m_filter, this);
    m_view->setObjectName(QStringLiteral("axisStatusView"));
    m_view->setModel(m_filter);
    m_view->verticalHeader()->hide();
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setShowGrid(false);
    // Column widths from the headers and the widest name, once: the list never re-flows
    // while the status changes.
    m_view->resizeColumnsToContents();
    // Room for the widest texts these columns take (a position, a silent drive), reserved.
    const QFontMetrics metrics = m_view->fontMetrics();
    const int pad = 2 * metrics.averageCharWidth();
    QHeaderView* header = m_view->horizontalHeader();
    header->resizeSection(AxisStatusModel::Position,
                          qMax(header->sectionSize(AxisStatusModel::Position),
                               metrics.horizontalAdvance(QStringLiteral("~-2147483648 ?")) + pad));
    header->resizeSection(
        AxisStatusModel::Drive,
        qMax(header->sectionSize(AxisStatusModel::Drive),
             metrics.horizontalAdvance(AxisStatusModel::tr("%1 \u2716 silent").arg(254)) + pad));
    header->setStretchLastSection(true);
    m_view->setMinimumHeight(8 * m_view->verticalHeader()->defaultSectionSize());
    auto* v = new QVBoxLayout(this);
    v->addWidget(m_bar);
    v->addWidget(m_view, 1);
    // One view per kind of word (Nanotec: the `$` word), showing the chosen drive's.
    for (const StatusWordInfo& w : axisWords) {
        if (m_kinds.contains(w.title))
            continue;
        m_kinds << w.title;
        auto* view = new RawWordView(w, this);
        m_wordViews << view;
        v->addWidget(view);
    }
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &AxisStatusList::followSelection);
    // Nothing selected: the words follow the first drive listed (after filtering, sorting).
    connect(m_filter, &QAbstractItemModel::layoutChanged, this, &AxisStatusList::followSelection);
    connect(m_filter, &QAbstractItemModel::rowsInserted, this, &AxisStatusList::followSelection);
    connect(m_filter, &QAbstractItemModel::rowsRemoved, this, &AxisStatusList::followSelection);
    followSelection();
}

AxisStatusList::~AxisStatusList()
{
    // QWidget deletes the children (model, filter, view) after this object's members are gone:
    // none of their signals may reach followSelection() then.
    m_filter->disconnect(this);
    m_view->selectionModel()->disconnect(this);
}

void AxisStatusList::setStatus(const MachineStatus& status, bool live)
{
    m_status = status;
    m_live = live;
    m_model->setStatus(status, live);
    showWordsOf(m_wordAxis);
}

void AxisStatusList::followSelection()
{
    const QModelIndexList selected = m_view->selectionModel()->selectedRows();
    QModelIndex row = selected.isEmpty() ? m_filter->index(0, 0) : selected.first();
    if (!row.isValid()) {
        showWordsOf(std::nullopt);
        return;
    }
    showWordsOf(m_model->axisAt(m_filter->mapToSource(row).row()));
}

void AxisStatusList::showWordsOf(std::optional<Axis> axis)
{
    m_wordAxis = axis;
    for (int i = 0; i < m_wordViews.size(); ++i) {
        RawWordView* view = m_wordViews.at(i);
        const std::optional<StatusWordInfo> word =
            axis ? wordOf(m_axisWords, m_kinds.at(i), *axis) : std::nullopt;
        if (!word) {
            view->setValue({});
            continue;
        }
        view->retarget(word->key,
                       tr("%1: %2").arg(m_context->controllerAxisName(*axis), word->title));
        view->setValue(m_live ? m_status.raw.value(word->key) : QVariant());
    }
}

} // namespace stepdeck::ui
