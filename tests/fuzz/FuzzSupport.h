#pragma once
// Shared by the libFuzzer targets (tests/fuzz/fuzz_*.cpp): deterministic splitting of an
// input into chunks, and the invariant check that aborts (libFuzzer then saves the input).
#include <QByteArray>
#include <QList>
#include <QString>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(condition, detail)                                                              \
    do {                                                                                           \
        if (!(condition)) {                                                                        \
            std::fprintf(stderr, "invariant failed: %s\n  %s\n  at %s:%d\n", #condition,           \
                         qPrintable(QString(detail)), __FILE__, __LINE__);                         \
            std::abort();                                                                          \
        }                                                                                          \
    } while (0)

namespace fuzz {

inline QByteArray input(const uint8_t* data, size_t size)
{
    return QByteArray(reinterpret_cast<const char*>(data), qsizetype(size));
}

// Chunk lengths 1..16 drawn from a small generator seeded by the input itself: the same
// input always splits the same way, different inputs split differently.
inline QList<QByteArray> split(const QByteArray& data)
{
    quint32 state = 2166136261u; // FNV-1a of the data seeds an xorshift generator
    for (char c : data)
        state = (state ^ quint8(c)) * 16777619u;
    QList<QByteArray> chunks;
    for (qsizetype i = 0; i < data.size();) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        const qsizetype n = 1 + qsizetype(state % 16);
        chunks << data.mid(i, n);
        i += n;
    }
    return chunks;
}

inline QList<QByteArray> bytes(const QByteArray& data)
{
    QList<QByteArray> out;
    for (char c : data)
        out << QByteArray(1, c);
    return out;
}

// A decoder fed the chunks; after every feed `check(decoder)` may assert bounds.
template <typename Decoder, typename Frame, typename Check>
QList<Frame> decodeChunks(Decoder& decoder, const QList<QByteArray>& chunks, Check check)
{
    QList<Frame> out;
    for (const QByteArray& chunk : chunks) {
        out += decoder.feed(chunk);
        check(decoder);
    }
    return out;
}

template <typename T, typename Same> bool sameLists(const QList<T>& a, const QList<T>& b, Same same)
{
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (!same(a[i], b[i]))
            return false;
    }
    return true;
}

inline QString hex(const QByteArray& bytes)
{
    return QString::fromLatin1(bytes.toHex(' '));
}

// Reads little-endian integers from the input for the encoder round trips.
class Reader
{
public:
    explicit Reader(const QByteArray& data) : m_data(data) {}
    quint64 next(int byteCount)
    {
        quint64 v = 0;
        for (int i = 0; i < byteCount; ++i) {
            const quint8 b = m_pos < m_data.size() ? quint8(m_data.at(m_pos)) : 0;
            ++m_pos;
            v |= quint64(b) << (8 * i);
        }
        return v;
    }
    bool atEnd() const { return m_pos >= m_data.size(); }

private:
    QByteArray m_data;
    qsizetype m_pos = 0;
};

} // namespace fuzz
