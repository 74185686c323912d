#include "ProgramFiles.h"
#include "ProgramEditor.h"
#include "common/Dialogs.h"
#include "common/ElidedLabel.h"
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QMenu>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QToolButton>

namespace stepdeck::ui {

namespace recentprograms {
namespace {
const QString kRecent = QStringLiteral("programs/recent");
}

QStringList list()
{
    QStringList paths = QSettings().value(kRecent).toStringList();
    paths.removeAll(QString());
    paths.removeDuplicates();
    return paths.mid(0, kMaxRecentPrograms);
}

void add(const QString& path)
{
    const QString file = QFileInfo(path).absoluteFilePath();
    QStringList paths = list();
    paths.removeAll(file);
    paths.prepend(file);
    QSettings().setValue(kRecent, paths.mid(0, kMaxRecentPrograms));
}

void remove(const QString& path)
{
    QStringList paths = list();
    paths.removeAll(QFileInfo(path).absoluteFilePath());
    QSettings().setValue(kRecent, paths);
}
} // namespace recentprograms

namespace {
const QString kDialogKey = QStringLiteral("programs");
QString filter()
{
    return ProgramFiles::tr("Motion programs (*.ngc *.nc *.gcode);;All files (*)");
}
} // namespace

ProgramFiles::ProgramFiles(QPlainTextEdit* editor, QWidget* parent)
    : QWidget(parent), m_editor(editor), m_open(new QPushButton(tr("&Open\u2026"), this)),
      m_save(new QPushButton(tr("&Save"), this)),
      m_saveAs(new QPushButton(tr("Save &as\u2026"), this)), m_recent(new QToolButton(this)),
      m_recentMenu(new QMenu(this)), m_name(new ElidedLabel(this))
{
    setObjectName(QStringLiteral("programFiles"));
    m_open->setObjectName(QStringLiteral("programOpen"));
    m_save->setObjectName(QStringLiteral("programSave"));
    m_recent->setObjectName(QStringLiteral("programRecent"));
    m_name->setObjectName(QStringLiteral("programFileName"));
    m_recent->setText(tr("Recent"));
    m_recent->setMenu(m_recentMenu);
    m_recent->setPopupMode(QToolButton::InstantPopup);
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(m_open);
    h->addWidget(m_recent);
    h->addWidget(m_save);
    h->addWidget(m_saveAs);
    h->addWidget(m_name, 1);
    connect(m_open, &QPushButton::clicked, this, &ProgramFiles::chooseToOpen);
    connect(m_save, &QPushButton::clicked, this, &ProgramFiles::save);
    connect(m_saveAs, &QPushButton::clicked, this, &ProgramFiles::chooseToSaveAs);
    connect(m_editor->document(), &QTextDocument::modificationChanged, this,
            &ProgramFiles::updateName);
    connect(m_recentMenu, &QMenu::aboutToShow, this, &ProgramFiles::rebuildRecentMenu);
    rebuildRecentMenu();
    updateName();
}

bool ProgramFiles::isModified() const
{
    return m_editor->document()->isModified();
}

void ProgramFiles::chooseToOpen()
{
    dialogs::openFile(this, kDialogKey, tr("Open program"), filter(),
                      [this](const QString& path) { openAsked(path); });
}

void ProgramFiles::openAsked(const QString& path)
{
    if (!isModified()) {
        load(path);
        return;
    }
    dialogs::message(this, QMessageBox::Question, tr("Open program"),
                     tr("The program shown has unsaved changes. Discard them and open %1?")
                         .arg(QFileInfo(path).fileName()),
                     QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel,
                     [this, path](QMessageBox::StandardButton b) {
                         if (b == QMessageBox::Discard)
                             load(path);
                     });
}

bool ProgramFiles::load(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        Q_EMIT message(tr("Program %1: cannot be read: %2").arg(path, file.errorString()));
        recentprograms::remove(path);
        return false;
    }
    const bool large = file.size() > kMaxEditBytes;
    if (large) {
        if (!loadExcerpt(&file))
            return false;
    } else {
        const QByteArray bytes = file.readAll();
        if (bytes.size() != file.size()) {
            Q_EMIT message(tr("Program %1: cannot be read: %2").arg(path, file.errorString()));
            return false;
        }
        m_editor->setPlainText(QString::fromUtf8(bytes));
    }
    setLarge(large);
    m_editor->document()->setModified(false);
    m_path = QFileInfo(path).absoluteFilePath();
    recentprograms::add(m_path);
    updateName();
    Q_EMIT loaded(m_path); // the page drops what it said of the program before
    if (large)
        Q_EMIT message(tr("%1 is %2 MB: too large to edit here. Its first %3 lines are shown; the "
                          "check, the preview and the run read the whole file.")
                           .arg(QFileInfo(path).fileName())
                           .arg(double(file.size()) / (1024 * 1024), 0, 'f', 1)
                           .arg(kExcerptLines));
    return true;
}

bool ProgramFiles::loadExcerpt(QFile* file)
{
    QByteArray head;
    for (int i = 0; i < kExcerptLines && !file->atEnd(); ++i) {
        const QByteArray line = file->readLine(64 * 1024);
        if (line.isEmpty() && file->error() != QFileDevice::NoError) {
            Q_EMIT message(
                tr("Program %1: cannot be read: %2").arg(file->fileName(), file->errorString()));
            return false;
        }
        head += line;
    }
    if (head.endsWith('\n'))
        head.chop(1);
    m_editor->setPlainText(QString::fromUtf8(head));
    return true;
}

void ProgramFiles::setLarge(bool large)
{
    m_large = large;
    if (auto* editor = qobject_cast<ProgramEditor*>(m_editor))
        editor->setExcerpt(large); // stays read-only after a run, too
    else
        m_editor->setReadOnly(large);
    m_save->setEnabled(!large);
    m_saveAs->setEnabled(!large);
}

bool ProgramFiles::saveTo(const QString& path)
{
    if (m_large)
        return false; // the editor holds an excerpt: it must never replace a file
    QSaveFile file(path);
    const QByteArray bytes = m_editor->toPlainText().toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        Q_EMIT message(tr("Program %1: cannot be written: %2").arg(path, file.errorString()));
        return false;
    }
    m_editor->document()->setModified(false);
    m_path = QFileInfo(path).absoluteFilePath();
    recentprograms::add(m_path);
    updateName();
    return true;
}

void ProgramFiles::save()
{
    if (m_path.isEmpty())
        chooseToSaveAs();
    else
        saveTo(m_path);
}

void ProgramFiles::chooseToSaveAs()
{
    const QString name =
        m_path.isEmpty() ? QStringLiteral("program.ngc") : QFileInfo(m_path).fileName();
    dialogs::saveFile(this, kDialogKey, tr("Save program"), name, filter(),
                      [this](const QString& path) { saveTo(path); });
}

void ProgramFiles::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList paths = recentprograms::list();
    for (const QString& path : paths)
        m_recentMenu->addAction(path, this, [this, path] { openAsked(path); });
    if (paths.isEmpty())
        m_recentMenu->addAction(tr("No recent programs"))->setEnabled(false);
}

void ProgramFiles::updateName()
{
    QString name = m_path.isEmpty() ? tr("Untitled") : QFileInfo(m_path).fileName();
    if (isModified())
        name += QStringLiteral(" *");
    m_name->setText(name);
    m_name->setToolTip(m_path);
}

QString ProgramFiles::fileText() const
{
    return m_name->text();
}

} // namespace stepdeck::ui
