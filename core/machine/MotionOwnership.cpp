#include "MotionOwnership.h"

namespace stepdeck::machine {

bool MotionOwnership::claim(const QObject* owner, const QString& what, QString* why)
{
    if (!m_owner.isNull() && m_owner.data() != owner) {
        if (why)
            *why = m_what;
        return false;
    }
    // QPointer watches the owner's destruction; it never changes the owner.
    if (m_owner.data() != owner)
        m_lent = false;
    m_owner = const_cast<QObject*>(owner);
    m_what = what;
    return true;
}

void MotionOwnership::release(const QObject* owner)
{
    if (!m_owner.isNull() && m_owner.data() == owner) {
        m_owner.clear();
        m_what.clear();
        m_lent = false;
    }
}

void MotionOwnership::setLent(const QObject* owner, bool lent)
{
    if (isHeldBy(owner))
        m_lent = lent;
}

bool MotionOwnership::isHeldBy(const QObject* owner) const
{
    return owner && !m_owner.isNull() && m_owner.data() == owner;
}

QString MotionOwnership::holder() const
{
    return m_owner.isNull() ? QString() : m_what;
}

} // namespace stepdeck::machine
