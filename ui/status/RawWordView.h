#pragma once
#include "model/ModelPresentation.h"
#include <QGroupBox>

class QLabel;

namespace stepdeck::ui {

class LedIndicator;

// One raw status word of the model: its value in hex and one lamp per documented bit, named
// as in the manual, with plain words in the tooltip.
class RawWordView : public QGroupBox
{
    Q_OBJECT
public:
    explicit RawWordView(const StatusWordInfo& info, QWidget* parent = nullptr);

    void setValue(const QVariant& value); // invalid: unknown (not read yet)
    QString hexText() const;
    LedIndicator* lamp(const QString& bitName) const;
    const StatusWordInfo& info() const { return m_info; }

private:
    StatusWordInfo m_info;
    QLabel* m_hex;
    QList<QPair<StatusBitInfo, LedIndicator*>> m_lamps;
};

} // namespace stepdeck::ui
