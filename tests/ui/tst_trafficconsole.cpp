// Traffic console: E-LAB mnemonics through the model's presentation, hex toggle, hidden
// polls, pause, and a send line that accepts the same notation and refuses bad input.
#include "TestMain.h"
#include "UiTestSupport.h"
#include "console/TrafficConsole.h"
#include <QCheckBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>

using namespace stepdeck;
using namespace stepdeck::test;

class TestTrafficConsole : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void format_elabBytes_showsMnemonics_data();
    void format_elabBytes_showsMnemonics();
    void hexToggle_showsHexBytes();
    void polls_hiddenByDefault_shownOnRequest();
    void pause_freezesView();
    void refresh_onlyWhileOnTop_catchesUpWhenRaised();
    void sendLine_mnemonic_sentAsBytes();
    void sendLine_badMnemonic_notSentAndSaysWhy();
    void save_writesVisibleLines();
    void sendHint_inTheConnectedModelsNotation();

private:
    ui::TrafficConsole* console() const { return m_f->window->trafficConsole(); }
    std::unique_ptr<UiFixture> m_f;
};

void TestTrafficConsole::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectSim());
}

void TestTrafficConsole::format_elabBytes_showsMnemonics_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("text");
    QTest::newRow("ramp") << QByteArray("\x1bS0064,0064;0064.")
                          << QStringLiteral("<ESC>S0064,0064;0064.");
    QTest::newRow("ack") << QByteArray("\x06") << QStringLiteral("<ACK>");
    QTest::newRow("machine state") << QByteArray("\x05"
                                                 "0080#")
                                   << QStringLiteral("<ENQ>0080#");
}

void TestTrafficConsole::format_elabBytes_showsMnemonics()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, text);
    QCOMPARE(console()->formatBytes(bytes), text);
    TrafficRecord r;
    r.bytes = bytes;
    r.timestampUs = 1500000;
    QVERIFY(console()->format(r).contains(text));
    QVERIFY(console()->format(r).contains(QStringLiteral("1.500000")));
}

void TestTrafficConsole::hexToggle_showsHexBytes()
{
    console()->hexCheck()->setChecked(true);
    QCOMPARE(console()->formatBytes(QByteArray("\x1bS0", 3)), QStringLiteral("1B 53 30"));
}

void TestTrafficConsole::polls_hiddenByDefault_shownOnRequest()
{
    QVERIFY(console()->hidePollsCheck()->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount > 5, 3000);
    console()->clear(); // from here on the fixture and the console see the same records
    const qsizetype from = m_f->records.size();
    const int before = m_f->statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount - before > 5, 3000);
    console()->flush();
    auto lines = [&] {
        const QString text = console()->visibleText();
        return text.isEmpty() ? 0 : int(text.count(QLatin1Char('\n')) + 1);
    };
    qsizetype polls = 0;
    for (qsizetype i = from; i < m_f->records.size(); ++i)
        polls += m_f->records.at(i).poll ? 1 : 0;
    QVERIFY(polls > 5);
    QCOMPARE(lines(), int(m_f->records.size() - from - polls));
    console()->hidePollsCheck()->setChecked(false);
    QVERIFY(lines() >= int(m_f->records.size() - from));
    QVERIFY(console()->visibleText().contains(QStringLiteral("<ENQ>")));
}

void TestTrafficConsole::pause_freezesView()
{
    console()->hidePollsCheck()->setChecked(false);
    console()->pauseCheck()->setChecked(true);
    const QString frozen = console()->visibleText();
    const int from = m_f->statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount - from > 5, 3000);
    console()->flush();
    QCOMPARE(console()->visibleText(), frozen);
    console()->pauseCheck()->setChecked(false);
    QVERIFY(console()->visibleText() != frozen); // everything recorded meanwhile appears
}

// Behind another tab the console draws nothing (issue 21: its 10 Hz refresh re-laid out the
// hidden dock for nobody); brought on top it shows at once what arrived meanwhile.
void TestTrafficConsole::refresh_onlyWhileOnTop_catchesUpWhenRaised()
{
    auto* dock = m_f->window->findChild<QDockWidget*>(QStringLiteral("trafficDock"));
    QVERIFY(dock);
    QTRY_VERIFY(!console()->isRefreshing()); // behind the Setup tab in the default layout
    console()->hidePollsCheck()->setChecked(false);
    const QString before = console()->visibleText();
    const int from = m_f->statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount - from > 5, 3000);
    QCOMPARE(console()->visibleText(), before);

    dock->raise();
    QTRY_VERIFY(console()->isRefreshing());
    const QString shown = console()->visibleText();
    QVERIFY(shown.size() > before.size());
    QVERIFY(shown.startsWith(before));
}

void TestTrafficConsole::sendLine_mnemonic_sentAsBytes()
{
    const qsizetype start = m_f->records.size();
    console()->sendLine()->setText(QStringLiteral("<ETB>"));
    QVERIFY(console()->sendCurrentLine());
    QTRY_VERIFY_WITH_TIMEOUT(m_f->sent(start).contains(char(elab::ctrl::ETB)), 3000);
    QVERIFY(console()->sendError()->text().isEmpty());
}

void TestTrafficConsole::sendLine_badMnemonic_notSentAndSaysWhy()
{
    const qsizetype start = m_f->records.size();
    console()->sendLine()->setText(QStringLiteral("<BOGUS>12"));
    QVERIFY(!console()->sendCurrentLine());
    QVERIFY(console()->sendError()->text().startsWith(QStringLiteral("Not sent")));
    QVERIFY(m_f->sent(start).isEmpty());
}

void TestTrafficConsole::save_writesVisibleLines()
{
    console()->hidePollsCheck()->setChecked(false);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount > 3, 3000);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("t.log"));
    QString error;
    QVERIFY2(console()->saveToFile(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    QVERIFY(text.contains(QStringLiteral("<ENQ>")));
    QVERIFY(text.contains(QStringLiteral("\u2192")));
}

// Issue 31 (a finding): the send line's hint showed E-LAB syntax on every model.
void TestTrafficConsole::sendHint_inTheConnectedModelsNotation()
{
    auto* send = console()->findChild<QLineEdit*>(QStringLiteral("trafficSend"));
    QVERIFY(send);
    QVERIFY2(send->placeholderText().contains(QStringLiteral("<ENQ>")),
             qPrintable(send->placeholderText()));
    ConnectionSpec spec{QStringLiteral("sim"), {}, {}};
    QString error;
    QVERIFY2(m_f->window->context()->connectTo(*findModel(QStringLiteral("nanotec")), spec, &error),
             qPrintable(error));
    QVERIFY(m_f->waitConnected());
    QTRY_VERIFY2(send->placeholderText().contains(QStringLiteral("#1$")),
                 qPrintable(send->placeholderText()));
    QVERIFY(!send->placeholderText().contains(QStringLiteral("<ENQ>")));
}

STEPDECK_TEST_MAIN(TestTrafficConsole)
#include "tst_trafficconsole.moc"
