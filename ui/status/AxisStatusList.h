#pragma once
#include "model/MachineStatus.h"
#include "model/ModelPresentation.h"
#include <QGroupBox>

class QTableView;

namespace stepdeck::ui {

class AxisListBar;
class AxisRowFilter;
class AxisStatusModel;
class MachineContext;
class RawWordView;

// The status page's axes of a controller with more of them than its lamp grid shows (a
// Nanotec bus of up to 254 drives; issue 32, step 5): a filtered list, the moving ones first
// on request, and below it the raw words of one drive (the `$` word, 5.21): the drive selected
// in the list, the first one listed until the operator picks one.
class AxisStatusList : public QGroupBox
{
    Q_OBJECT
public:
    // `axisWords`: the model's words that belong to one axis each (StatusWordInfo::axis).
    AxisStatusList(MachineContext* context, const QList<StatusWordInfo>& axisWords,
                   QWidget* parent = nullptr);
    ~AxisStatusList() override;

    void setStatus(const MachineStatus& status, bool live);
    QTableView* view() const { return m_view; }
    AxisListBar* bar() const { return m_bar; }
    AxisRowFilter* filter() const { return m_filter; }
    AxisStatusModel* model() const { return m_model; }
    // The drive whose words show; nullopt: none (no axis listed).
    std::optional<Axis> wordAxis() const { return m_wordAxis; }
    const QList<RawWordView*>& wordViews() const { return m_wordViews; }

private:
    void showWordsOf(std::optional<Axis> axis);
    void followSelection();

    MachineContext* m_context;
    AxisStatusModel* m_model;
    AxisRowFilter* m_filter;
    AxisListBar* m_bar;
    QTableView* m_view;
    QList<StatusWordInfo> m_axisWords; // every axis' words, by axis
    QList<RawWordView*> m_wordViews;   // one per kind of word, showing m_wordAxis'
    QStringList m_kinds;               // the model's title of each view's kind of word
    std::optional<Axis> m_wordAxis;
    MachineStatus m_status;
    bool m_live = false;
};

} // namespace stepdeck::ui
