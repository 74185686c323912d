#pragma once
#include <QStringList>
#include <QWidget>

class QFile;
class QMenu;
class QPlainTextEdit;
class QPushButton;
class QToolButton;

namespace stepdeck::ui {

class ElidedLabel;

namespace recentprograms {
constexpr int kMaxRecentPrograms = 8;
QStringList list(); // QSettings "programs/recent", most recent first
void add(const QString& path);
void remove(const QString& path);
} // namespace recentprograms

// Open, Save, Save as and the recent programs of the Program page (issue 20), for the text of
// one editor. Files are UTF-8 text; one that cannot be read is refused with the reason
// (message()), and the editor keeps what it had. Unsaved changes are not dropped by Open: a
// non-modal question comes first. A file larger than kMaxEditBytes (a CAM program of millions
// of lines, issue 29) is not loaded into the editor: it shows its first kExcerptLines lines,
// read-only, and the check, the preview and the run read the file itself (largePath()); Save
// and Save as are off then, so that the excerpt can never replace the file.
class ProgramFiles : public QWidget
{
    Q_OBJECT
public:
    static constexpr qint64 kMaxEditBytes = 8 * 1024 * 1024;
    static constexpr int kExcerptLines = 2000;

    ProgramFiles(QPlainTextEdit* editor, QWidget* parent = nullptr);

    QString currentPath() const { return m_path; }
    // The file shown as an excerpt (too large to edit); empty when the editor holds the text.
    QString largePath() const { return m_large ? m_path : QString(); }
    bool isModified() const;
    // Reads path into the editor; false (editor unchanged) with the reason in message().
    bool load(const QString& path);
    bool saveTo(const QString& path);
    QPushButton* openButton() const { return m_open; }
    QPushButton* saveButton() const { return m_save; }
    QToolButton* recentButton() const { return m_recent; }
    QString fileText() const; // the file name shown

public Q_SLOTS:
    void chooseToOpen();
    void save(); // to the current file; without one: Save as
    void chooseToSaveAs();

Q_SIGNALS:
    void loaded(const QString& path);
    void message(const QString& text); // a file that could not be read or written

private:
    void openAsked(const QString& path); // after the unsaved-changes question
    void setLarge(bool large);
    bool loadExcerpt(QFile* file);
    void rebuildRecentMenu();
    void updateName();

    QPlainTextEdit* m_editor;
    QString m_path;
    bool m_large = false;
    QPushButton* m_open;
    QPushButton* m_save;
    QPushButton* m_saveAs;
    QToolButton* m_recent;
    QMenu* m_recentMenu;
    ElidedLabel* m_name;
};

} // namespace stepdeck::ui
