// The status bar's message line and the message log (issue 16): a message of any length is
// one line (elided, the full text in the tooltip), its size never depends on the text, a
// label re-elides when its width changes, and the log keeps every message with date and time,
// bounded.
#include "TestMain.h"
#include "common/ElidedLabel.h"
#include "messages/MessageLine.h"
#include "messages/MessageLog.h"
#include "messages/StatusMessages.h"
#include <QApplication>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QToolButton>
#include <QtTest>

using stepdeck::ui::ElidedLabel;
using stepdeck::ui::MessageLine;
using stepdeck::ui::MessageLog;
using stepdeck::ui::StatusMessages;
using Owner = StatusMessages::Owner;

namespace {
const QString kShort = QStringLiteral("Stop sent");
QString longText()
{
    QString text;
    for (int i = 0; i < 12; ++i)
        text += QStringLiteral("this controller has no stop command; use the emergency stop. ");
    return text.trimmed();
}
} // namespace

class TestMessageLine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void label_sizeNeverFollowsText_data();
    void label_sizeNeverFollowsText();
    void label_longText_elidedFullTextInTooltip_data();
    void label_longText_elidedFullTextInTooltip();
    void label_resized_reElides();
    void label_reservedTexts_heightOfTheLongestAtEveryWidth();
    void line_longMessage_oneLineFullTextInTooltip();
    void line_countsMessagesUntilTheLogIsOnScreen();
    void log_everyMessageWithDateAndTime_bounded();
};

void TestMessageLine::label_sizeNeverFollowsText_data()
{
    QTest::addColumn<int>("lines");
    QTest::newRow("one line") << 1;
    QTest::newRow("two lines") << 2;
}

void TestMessageLine::label_sizeNeverFollowsText()
{
    QFETCH(int, lines);
    ElidedLabel label(nullptr, lines);
    const QSize empty = label.sizeHint();
    const QSize emptyMinimum = label.minimumSizeHint();
    label.setText(longText());
    QCOMPARE(label.sizeHint(), empty);
    QCOMPARE(label.minimumSizeHint(), emptyMinimum);
    QVERIFY(!label.hasHeightForWidth());
    // Room for exactly `lines` lines.
    const QFontMetrics fm = label.fontMetrics();
    QCOMPARE(empty.height(), fm.height() + (lines - 1) * fm.lineSpacing() +
                                 label.contentsMargins().top() + label.contentsMargins().bottom());
}

void TestMessageLine::label_longText_elidedFullTextInTooltip_data()
{
    QTest::addColumn<int>("lines");
    QTest::newRow("one line") << 1;
    QTest::newRow("two lines") << 2;
}

void TestMessageLine::label_longText_elidedFullTextInTooltip()
{
    QFETCH(int, lines);
    ElidedLabel label(nullptr, lines);
    label.setToolTip(QStringLiteral("what this label says"));
    label.resize(300, label.sizeHint().height());
    label.setText(kShort);
    QVERIFY(!label.isElided());
    QCOMPARE(label.shownLines(), QStringList{kShort});
    QCOMPARE(label.toolTipText(), QStringLiteral("what this label says"));

    label.setText(longText());
    QVERIFY(label.isElided());
    const QStringList shown = label.shownLines();
    QCOMPARE(shown.size(), lines);
    QVERIFY2(shown.constLast().endsWith(QChar(0x2026)), qPrintable(shown.constLast()));
    for (const QString& line : shown)
        QVERIFY(label.fontMetrics().horizontalAdvance(line) <= 300);
    QCOMPARE(label.text(), longText()); // text() stays the full text
    QVERIFY(label.toolTipText().startsWith(longText()));
    QVERIFY(label.toolTipText().endsWith(QStringLiteral("what this label says")));
}

void TestMessageLine::label_resized_reElides()
{
    ElidedLabel label;
    label.setText(QStringLiteral("Written: Start speed, Max speed, Acceleration."));
    label.resize(2000, label.sizeHint().height());
    QVERIFY(!label.isElided());
    label.resize(120, label.sizeHint().height());
    QVERIFY(label.isElided());
    QVERIFY(label.fontMetrics().horizontalAdvance(label.shownLines().constFirst()) <= 120);
    label.resize(2000, label.sizeHint().height());
    QVERIFY(!label.isElided());
}

void TestMessageLine::label_reservedTexts_heightOfTheLongestAtEveryWidth()
{
    ElidedLabel label;
    label.setReservedTexts({kShort, longText()});
    QVERIFY(label.hasHeightForWidth());
    const int wide = label.heightForWidth(1200);
    const int narrow = label.heightForWidth(400);
    QVERIFY2(narrow > wide, qPrintable(QStringLiteral("%1 %2").arg(narrow).arg(wide)));
    // At the reserved height every reserved text shows in full, the longest included.
    for (const QString& text : {kShort, longText()}) {
        label.setText(text);
        label.resize(400, narrow);
        QVERIFY2(!label.isElided(), qPrintable(label.shownLines().join('|')));
        label.resize(1200, wide);
        QVERIFY(!label.isElided());
    }
    // The text shown does not change the height asked for.
    label.setText(kShort);
    QCOMPARE(label.heightForWidth(400), narrow);
}

void TestMessageLine::line_longMessage_oneLineFullTextInTooltip()
{
    StatusMessages messages;
    MessageLine line(&messages);
    line.resize(600, line.sizeHint().height());
    line.show();
    const QSize before = line.sizeHint();
    const QSize minimumBefore = line.minimumSizeHint();
    messages.show(Owner::Request, longText());
    QCOMPARE(line.sizeHint(), before);
    QCOMPARE(line.minimumSizeHint(), minimumBefore);
    QCOMPARE(line.label()->text(), messages.currentLine());
    QVERIFY(line.label()->isElided());
    QCOMPARE(line.label()->shownLines().size(), 1);
    QVERIFY(line.label()->toolTipText().contains(longText()));
    messages.clearAll();
    QCOMPARE(line.label()->text(), QString());
    QCOMPARE(line.sizeHint(), before);
}

void TestMessageLine::line_countsMessagesUntilTheLogIsOnScreen()
{
    StatusMessages messages;
    MessageLine line(&messages);
    QSignalSpy requested(&line, &MessageLine::logRequested);
    const int width = line.logButton()->width();
    QCOMPARE(line.logButton()->text(), QStringLiteral("Messages"));
    messages.show(Owner::Link, QStringLiteral("link lost"));
    messages.show(Owner::Jog, QStringLiteral("jog refused"));
    QCOMPARE(line.unseen(), 2);
    QCOMPARE(line.logButton()->text(), QStringLiteral("Messages (2)"));
    QCOMPARE(line.logButton()->width(), width); // a count never moves the line
    line.logButton()->click();
    QCOMPARE(requested.count(), 1);
    line.setLogOnScreen(true);
    QCOMPARE(line.unseen(), 0);
    messages.show(Owner::Setup, QStringLiteral("read"), StatusMessages::Severity::Info);
    QCOMPARE(line.unseen(), 0); // seen as it arrives
    line.setLogOnScreen(false);
    messages.show(Owner::Setup, QStringLiteral("written"), StatusMessages::Severity::Info);
    QCOMPARE(line.logButton()->text(), QStringLiteral("Messages (1)"));
}

void TestMessageLine::log_everyMessageWithDateAndTime_bounded()
{
    StatusMessages messages;
    messages.show(Owner::Link, QStringLiteral("shown before the log existed"));
    MessageLog log(&messages);
    messages.show(Owner::Request, longText());
    messages.clearAll(); // ended messages stay in the log
    QStringList lines = log.lines();
    QCOMPARE(lines.size(), 2);
    const QRegularExpression stamp(QStringLiteral("^\\d{4}-\\d\\d-\\d\\d \\d\\d:\\d\\d:\\d\\d  "));
    QVERIFY2(stamp.match(lines.at(0)).hasMatch(), qPrintable(lines.at(0)));
    QVERIFY(lines.at(0).endsWith(QStringLiteral("shown before the log existed")));
    QVERIFY(lines.at(1).endsWith(longText())); // in full, on one line
    for (int i = 0; i < StatusMessages::kLogLimit + 5; ++i)
        messages.show(Owner::General, QStringLiteral("message %1").arg(i));
    lines = log.lines();
    QCOMPARE(lines.size(), StatusMessages::kLogLimit);
    QVERIFY(lines.constFirst().endsWith(QStringLiteral("message 5")));
    QVERIFY(lines.constLast().endsWith(
        QStringLiteral("message %1").arg(StatusMessages::kLogLimit + 4)));
}

STEPDECK_TEST_MAIN(TestMessageLine)
#include "tst_messageline.moc"
