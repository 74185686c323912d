#pragma once
#include "Transport.h"
#include <QPointer>

namespace stepdeck {

// One end of an in-memory byte link. Bytes written on one end arrive on the other end's
// dataReceived() through the event loop (queued, so the ends may live in different threads).
// For unit tests and the in-process simulator; end-to-end tests use real pseudo-terminals.
class LoopbackTransport : public Transport
{
    Q_OBJECT
public:
    explicit LoopbackTransport(QObject* parent = nullptr);
    // Creates two connected ends.
    static std::pair<LoopbackTransport*, LoopbackTransport*> createPair(QObject* parent = nullptr);
    void setPeer(LoopbackTransport* peer) { m_peer = peer; }

    void open(const LineSettings& settings) override;
    void close() override;
    bool isOpen() const override { return m_open; }
    qint64 write(const QByteArray& bytes) override;
    void discardOutput() override;
    qint64 bytesToWrite() const override { return 0; }
    bool flushOutput(int) override { return m_open; } // bytes are handed over at write()
    QString description() const override { return QStringLiteral("loopback"); }

    // Test hook: the link breaks as if the peer vanished (emits failed once, closes).
    void simulateFailure(const QString& reason);
    LineSettings lineSettings() const { return m_settings; }
    quint64 generation() const { return m_generation; }

private:
    void deliver(const QByteArray& bytes, quint64 generation);

    QPointer<LoopbackTransport> m_peer;
    bool m_open = false;
    LineSettings m_settings;
    quint64 m_generation = 0; // bumped by discardOutput(): in-flight chunks are dropped
};

} // namespace stepdeck
