// Issue 11, "Fit the screen": the main window fits 1366x768 with every page reachable and
// is usable at 1024x768; STOP, PANIC, the link state and the last status message are always
// on screen. Checked offscreen with the default layout, connected to the simulator (the
// pages are filled), in English and with the longer German texts.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "jog/JogPanel.h"
#include "safety/SafetyBar.h"
#include "window/Translations.h"
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QStatusBar>
#include <QToolBar>

using namespace stepdeck;
using namespace stepdeck::test;

class TestWindowFit : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void cleanup() { m_f.reset(); }
    void screen_fitsAndShowsSafetyWidgets_data();
    void screen_fitsAndShowsSafetyWidgets();

private:
    static QString onScreen(QWidget* w, const QString& name);
    std::unique_ptr<UiFixture> m_f;
};

QString TestWindowFit::onScreen(QWidget* w, const QString& name)
{
    if (!w || !w->isVisible())
        return QStringLiteral("%1 is not visible").arg(name);
    QWidget* top = w->window();
    const QRect inWindow(w->mapTo(top, QPoint(0, 0)), w->size());
    if (!top->rect().contains(inWindow))
        return QStringLiteral("%1 at %2,%3 %4x%5 is cut off by the %6x%7 window")
            .arg(name)
            .arg(inWindow.x())
            .arg(inWindow.y())
            .arg(inWindow.width())
            .arg(inWindow.height())
            .arg(top->width())
            .arg(top->height());
    if (w->visibleRegion().isEmpty())
        return QStringLiteral("%1 is covered").arg(name);
    return {};
}

void TestWindowFit::screen_fitsAndShowsSafetyWidgets_data()
{
    QTest::addColumn<QSize>("screen");
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("model");
    // English first: a German translator, once installed, stays for the process. Every model:
    // EMIS adds the U axis, digital I/O and the input-program page, laser axes their jog note.
    for (const char* lang : {"en", "de"}) {
        for (const ModelInfo& model : models()) {
            for (const QSize size : {QSize(1366, 768), QSize(1024, 768)})
                QTest::addRow("%s %dx%d %s", qPrintable(model.id), size.width(), size.height(),
                              lang)
                    << size << QString::fromLatin1(lang) << model.id;
        }
    }
}

void TestWindowFit::screen_fitsAndShowsSafetyWidgets()
{
    QFETCH(QSize, screen);
    QFETCH(QString, language);
    QFETCH(QString, model);
    QSettings().clear();
    ui::translations::install(qApp, language);
    m_f = std::make_unique<UiFixture>();
    ui::MainWindow* w = m_f->window.get();
    w->show();
    w->connectionBar()->setSelectedModel(model);
    w->connectionBar()->setPortSpec(QStringLiteral("sim"));
    w->connectionBar()->connectNow();
    QVERIFY(m_f->waitConnected());
    QCOMPARE(w->context()->modelId(), model);
    QTRY_VERIFY(m_f->statusCount > 1);

    QString sizes;
    for (QDockWidget* dock : w->findChildren<QDockWidget*>()) {
        if (dock->isVisible())
            sizes += QStringLiteral(" %1 %2x%3;")
                         .arg(dock->objectName())
                         .arg(dock->minimumSizeHint().width())
                         .arg(dock->minimumSizeHint().height());
    }
    for (QWidget* part :
         {w->centralWidget(), static_cast<QWidget*>(w->safetyBar()),
          static_cast<QWidget*>(w->jogPanel()), static_cast<QWidget*>(w->connectionBar())})
        sizes += QStringLiteral(" %1 %2x%3;")
                     .arg(QString::fromLatin1(part->metaObject()->className()))
                     .arg(part->minimumSizeHint().width())
                     .arg(part->minimumSizeHint().height());
    const QSize minimum = w->minimumSizeHint().expandedTo(w->minimumSize());
    // A maximised window on such a screen leaves room for a panel or title bar.
    const QSize available = screen - QSize(0, 40);
    QVERIFY2(minimum.width() <= available.width() && minimum.height() <= available.height(),
             qPrintable(QStringLiteral("minimum %1x%2;%3")
                            .arg(minimum.width())
                            .arg(minimum.height())
                            .arg(sizes)));
    w->resize(available);
    QTRY_COMPARE(w->size(), available);
    QCoreApplication::processEvents();

    const QList<QPair<QWidget*, QString>> always{
        {w->safetyBar()->stopButton(), QStringLiteral("STOP")},
        {w->safetyBar()->panicButton(), QStringLiteral("PANIC")},
        {w->findChild<QWidget*>(QStringLiteral("safetyBanner")), QStringLiteral("banner")},
        {w->findChild<QWidget*>(QStringLiteral("linkState")), QStringLiteral("link state")},
        {w->findChild<QWidget*>(QStringLiteral("statusMessage")), QStringLiteral("status message")},
        {w->connectionBar()->connectButton(), QStringLiteral("Connect")},
    };
    for (const auto& [widget, name] : always) {
        const QString problem = onScreen(widget, name);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
    // Every page can be brought forward and is then on screen (a page larger than its dock
    // scrolls inside it).
    for (const auto& [stem, page] : w->pages()) {
        w->raisePage(page);
        QCoreApplication::processEvents();
        QWidget* dock = w->dockOf(page);
        const QString problem = onScreen(dock ? dock : page, stem);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
}

STEPDECK_TEST_MAIN(TestWindowFit)
#include "tst_windowfit.moc"
