// ScreenBound (issue 16): without a window manager a window whose layout's minimum grows
// past the screen was resized past the screen's edge (1366x871 on a 768-px screen after a
// reconnect). With ScreenBound the minimum stays within the screen's available geometry and
// the window stays on it; an explicit resize by the application is not its business.
#include "TestMain.h"
#include "window/ScreenBound.h"
#include <QApplication>
#include <QLabel>
#include <QScreen>
#include <QVBoxLayout>
#include <QtTest>

using stepdeck::ui::ScreenBound;

class TestScreenBound : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void growingMinimum_windowStaysOnScreen_data();
    void growingMinimum_windowStaysOnScreen();
    void shown_offScreen_movedAndShrunkOntoIt();
};

void TestScreenBound::growingMinimum_windowStaysOnScreen_data()
{
    QTest::addColumn<bool>("bound");
    QTest::newRow("without ScreenBound the window grows") << false;
    QTest::newRow("with ScreenBound") << true;
}

void TestScreenBound::growingMinimum_windowStaysOnScreen()
{
    QFETCH(bool, bound);
    const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
    QWidget window;
    auto* layout = new QVBoxLayout(&window);
    auto* content = new QLabel(QStringLiteral("content"), &window);
    layout->addWidget(content);
    if (bound)
        new ScreenBound(&window);
    window.resize(available.size() / 2);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // A child whose minimum grows past the screen, as a wrapping status line did.
    content->setMinimumHeight(available.height() + 200);
    QTRY_VERIFY(!window.layout()->geometry().isEmpty());
    QCoreApplication::sendPostedEvents();
    QCoreApplication::processEvents();
    const QSize room = ScreenBound::room(&window);
    if (!bound) {
        // The failure ScreenBound exists for: the layout grows the window off the screen.
        QVERIFY2(window.height() > room.height(), qPrintable(QString::number(window.height())));
        return;
    }
    QVERIFY2(window.height() <= room.height() && window.width() <= room.width(),
             qPrintable(QStringLiteral("%1x%2, room %3x%4")
                            .arg(window.width())
                            .arg(window.height())
                            .arg(room.width())
                            .arg(room.height())));
    QVERIFY(window.minimumHeight() <= room.height());
    // An explicit resize within the screen still works.
    window.resize(room.width() / 2, room.height() / 2);
    QTRY_COMPARE(window.size(),
                 QSize(room.width() / 2, room.height() / 2).expandedTo(window.minimumSize()));
}

void TestScreenBound::shown_offScreen_movedAndShrunkOntoIt()
{
    const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
    QWidget window;
    new ScreenBound(&window);
    window.resize(available.width() + 300, available.height() + 300);
    window.move(available.topLeft() + QPoint(100, 100));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_VERIFY2(available.contains(window.frameGeometry()),
                 qPrintable(QStringLiteral("%1,%2 %3x%4")
                                .arg(window.frameGeometry().x())
                                .arg(window.frameGeometry().y())
                                .arg(window.frameGeometry().width())
                                .arg(window.frameGeometry().height())));
}

STEPDECK_TEST_MAIN(TestScreenBound)
#include "tst_screenbound.moc"
