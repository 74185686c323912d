#pragma once
// Counts the events of one type delivered to a watched object (repaints, layout requests,
// tooltip changes: what a widget did, not what it was told).
#include <QEvent>
#include <QObject>

namespace stepdeck::test {

class EventCounter : public QObject
{
public:
    EventCounter(QObject* watched, QEvent::Type type) : m_type(type)
    {
        watched->installEventFilter(this);
    }
    int count = 0;

protected:
    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == m_type)
            ++count;
        return false;
    }

private:
    QEvent::Type m_type;
};

} // namespace stepdeck::test
