#include "Program.h"
#include <QFile>
#include <QFileInfo>
#include <algorithm>

namespace stepdeck::program {

ProgramSource ProgramSource::file(const QString& path)
{
    ProgramSource s;
    s.m_path = path;
    s.m_isFile = true;
    return s;
}

ProgramSource ProgramSource::bytes(const QByteArray& text)
{
    ProgramSource s;
    s.m_bytes = text;
    return s;
}

ProgramSource ProgramSource::temporaryFile(std::shared_ptr<QFile> file)
{
    ProgramSource s;
    s.m_path = file->fileName();
    s.m_isFile = true;
    s.m_keep = std::move(file);
    return s;
}

qint64 ProgramSource::size() const
{
    if (!m_isFile)
        return m_bytes.size();
    const QFileInfo info(m_path);
    return info.isFile() ? info.size() : -1;
}

ProgramSourceReader::ProgramSourceReader(const ProgramSource& source) : m_source(source) {}

ProgramSourceReader::~ProgramSourceReader() = default;

bool ProgramSourceReader::open(QString* error)
{
    if (!m_source.m_isFile) {
        m_size = m_source.m_bytes.size();
        return true;
    }
    m_file = std::make_unique<QFile>(m_source.m_path);
    if (!QFileInfo(m_source.m_path).isFile() || !m_file->open(QIODevice::ReadOnly)) {
        *error = tr("cannot read %1").arg(m_source.m_path);
        m_file.reset();
        return false;
    }
    m_size = m_file->size();
    return true;
}

QByteArray ProgramSourceReader::read(qint64 offset, qint64 length, QString* error)
{
    if (!m_source.m_isFile)
        return m_source.m_bytes.mid(offset, length);
    if (!m_file) {
        *error = tr("cannot read %1").arg(m_source.m_path);
        return {};
    }
    if (m_file->pos() != offset && !m_file->seek(offset)) {
        *error = tr("cannot read %1: %2").arg(m_source.m_path, m_file->errorString());
        return {};
    }
    QByteArray bytes = m_file->read(length);
    if (bytes.isEmpty() && m_file->error() != QFileDevice::NoError)
        *error = tr("cannot read %1: %2").arg(m_source.m_path, m_file->errorString());
    return bytes;
}

size_t ProgramIndex::checkpointOfBlock(int block) const
{
    const auto it =
        std::upper_bound(checkpoints.cbegin(), checkpoints.cend(), block,
                         [](int b, const ProgramCheckpoint& c) { return b < c.state.blocks; });
    return it == checkpoints.cbegin() ? 0 : size_t(it - checkpoints.cbegin()) - 1;
}

size_t ProgramIndex::checkpointOfLine(int line) const
{
    // Checkpoint k starts before line state.line + 1.
    const auto it =
        std::upper_bound(checkpoints.cbegin(), checkpoints.cend(), line,
                         [](int l, const ProgramCheckpoint& c) { return l <= c.state.line; });
    return it == checkpoints.cbegin() ? 0 : size_t(it - checkpoints.cbegin()) - 1;
}

quint64 hashLine(quint64 hash, const char* data, qsizetype size)
{
    // FNV-1a over the line and its length: enough to notice a file edited since the check
    // (not a defence against someone who wants a collision).
    for (qsizetype i = 0; i < size; ++i) {
        hash ^= quint8(data[i]);
        hash *= 1099511628211ULL;
    }
    hash ^= quint64(size) + 0x9E3779B97F4A7C15ULL;
    return hash * 1099511628211ULL;
}

} // namespace stepdeck::program
