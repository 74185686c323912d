#pragma once
#include <QList>
#include <QVarLengthArray>
#include <algorithm>
#include <utility>

namespace stepdeck::program {

// The words of one line by name (a block's axes "X" -> value, its columns, a line's parameters
// 'F' -> word): QMap's interface and order (sorted by key) for the handful of entries a line
// has, kept in place. A program of millions of lines has millions of blocks; a QMap would
// allocate a node for each of their words (issue 29: the check reads 1 000 000 lines/s).
// Past Prealloc entries the storage moves to the heap, as QVarLengthArray's does.
template <typename Key, typename T, qsizetype Prealloc = 9> class WordMap
{
    using Entry = std::pair<Key, T>;
    using Storage = QVarLengthArray<Entry, Prealloc>;

public:
    template <typename Base, typename Value> class Iterator
    {
    public:
        using iterator_category = std::bidirectional_iterator_tag;
        using difference_type = qsizetype;
        using value_type = T;
        using pointer = Value*;
        using reference = Value&;

        Iterator() = default;
        explicit Iterator(Base it) : m_it(it) {}
        const Key& key() const { return m_it->first; }
        Value& value() const { return m_it->second; }
        Value& operator*() const { return m_it->second; }
        Value* operator->() const { return &m_it->second; }
        Iterator& operator++()
        {
            ++m_it;
            return *this;
        }
        Iterator operator++(int)
        {
            Iterator before = *this;
            ++m_it;
            return before;
        }
        Iterator& operator--()
        {
            --m_it;
            return *this;
        }
        bool operator==(const Iterator& o) const { return m_it == o.m_it; }
        bool operator!=(const Iterator& o) const { return m_it != o.m_it; }
        Base base() const { return m_it; }

    private:
        Base m_it{};
    };
    using iterator = Iterator<typename Storage::iterator, T>;
    using const_iterator = Iterator<typename Storage::const_iterator, const T>;
    using key_type = Key;
    using mapped_type = T;

    WordMap() = default;
    WordMap(std::initializer_list<Entry> entries)
    {
        for (const Entry& e : entries)
            insert(e.first, e.second);
    }

    bool isEmpty() const { return m_entries.isEmpty(); }
    qsizetype size() const { return m_entries.size(); }
    qsizetype count() const { return m_entries.size(); }
    void clear() { m_entries.clear(); }

    bool contains(const Key& key) const { return find(key) != end(); }
    T value(const Key& key, const T& fallback = T()) const
    {
        const const_iterator it = find(key);
        return it == end() ? fallback : it.value();
    }
    iterator insert(const Key& key, const T& value)
    {
        const auto at = lowerBound(key);
        if (at != m_entries.end() && at->first == key) {
            at->second = value;
            return iterator(at);
        }
        return iterator(m_entries.insert(at, Entry{key, value}));
    }
    qsizetype remove(const Key& key)
    {
        const auto at = lowerBound(key);
        if (at == m_entries.end() || !(at->first == key))
            return 0;
        m_entries.erase(at);
        return 1;
    }
    T take(const Key& key)
    {
        const T out = value(key);
        remove(key);
        return out;
    }
    T& operator[](const Key& key)
    {
        auto at = lowerBound(key);
        if (at == m_entries.end() || !(at->first == key))
            at = m_entries.insert(at, Entry{key, T()});
        return at->second;
    }
    T operator[](const Key& key) const { return value(key); }

    const T& first() const { return m_entries.front().second; }
    const Key& firstKey() const { return m_entries.front().first; }
    const T& last() const { return m_entries.back().second; }
    const Key& lastKey() const { return m_entries.back().first; }
    QList<Key> keys() const
    {
        QList<Key> out;
        out.reserve(size());
        for (const Entry& e : m_entries)
            out << e.first;
        return out;
    }
    QList<T> values() const
    {
        QList<T> out;
        out.reserve(size());
        for (const Entry& e : m_entries)
            out << e.second;
        return out;
    }

    iterator find(const Key& key)
    {
        const auto at = lowerBound(key);
        return iterator(at != m_entries.end() && at->first == key ? at : m_entries.end());
    }
    const_iterator find(const Key& key) const
    {
        // A line has a few words: a linear search beats a binary one at this size.
        for (auto it = m_entries.cbegin(); it != m_entries.cend(); ++it)
            if (it->first == key)
                return const_iterator(it);
        return end();
    }
    const_iterator constFind(const Key& key) const { return find(key); }
    iterator erase(const_iterator it)
    {
        const qsizetype i = it.base() - m_entries.cbegin();
        return iterator(m_entries.erase(m_entries.begin() + i));
    }

    iterator begin() { return iterator(m_entries.begin()); }
    iterator end() { return iterator(m_entries.end()); }
    const_iterator begin() const { return const_iterator(m_entries.cbegin()); }
    const_iterator end() const { return const_iterator(m_entries.cend()); }
    const_iterator cbegin() const { return begin(); }
    const_iterator cend() const { return end(); }
    const_iterator constBegin() const { return begin(); }
    const_iterator constEnd() const { return end(); }

    bool operator==(const WordMap& o) const
    {
        return std::equal(m_entries.cbegin(), m_entries.cend(), o.m_entries.cbegin(),
                          o.m_entries.cend());
    }
    bool operator!=(const WordMap& o) const { return !(*this == o); }

private:
    typename Storage::iterator lowerBound(const Key& key)
    {
        return std::lower_bound(m_entries.begin(), m_entries.end(), key,
                                [](const Entry& e, const Key& k) { return e.first < k; });
    }

    Storage m_entries;
};

} // namespace stepdeck::program
