#pragma once
#include "CanonicalMove.h"
#include <deque>

namespace stepdeck::motion {

// The moves a program has given that an executor has not finished laying out, in order; at
// most capacity() of them, so that a program of millions of blocks is read only as fast as the
// machine runs it (Klipper's toolhead keeps a bounded look-ahead the same way). STOP and PANIC
// never wait behind it: they go to the controllers directly and clear() drops what is left.
class MotionQueue
{
public:
    explicit MotionQueue(size_t capacity = 64) : m_capacity(capacity > 0 ? capacity : 1) {}

    size_t capacity() const { return m_capacity; }
    size_t size() const { return m_moves.size(); }
    bool isEmpty() const { return m_moves.empty(); }
    bool isFull() const { return m_moves.size() >= m_capacity; }

    // False when full: the caller offers it again once a move was taken.
    bool push(const CanonicalMove& move)
    {
        if (isFull())
            return false;
        m_moves.push_back(move);
        return true;
    }
    const CanonicalMove& front() const { return m_moves.front(); }
    const CanonicalMove& at(size_t i) const { return m_moves.at(i); }
    void pop() { m_moves.pop_front(); }
    void clear() { m_moves.clear(); }

private:
    size_t m_capacity;
    std::deque<CanonicalMove> m_moves;
};

} // namespace stepdeck::motion
