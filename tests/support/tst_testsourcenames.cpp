// The test files' own names (issue 48): the tests of a part of the tree are built into one
// program (tests/CMakeLists.txt, test groups), so a class, or an inline, constexpr or template
// function, defined at file scope outside an anonymous namespace in two test files would be
// one entity to the linker: it keeps one definition and one file's test silently runs the
// other's code. Two such names in one compiled batch break the compile; in two batches nothing
// does, so this test reads every test file and names each such entity defined twice.
#include "TestMain.h"
#include <QDirIterator>
#include <QMap>
#include <QRegularExpression>
#include <QtTest>
#include <algorithm>

namespace {

// The text without comments, string and character literals (raw strings too) and preprocessor
// lines, so that braces and words inside them do not count.
QString codeOnly(const QString& text)
{
    QString out;
    out.reserve(text.size());
    const int n = int(text.size());
    bool lineStart = true;
    for (int i = 0; i < n; ++i) {
        const QChar c = text.at(i);
        const QChar next = i + 1 < n ? text.at(i + 1) : QChar();
        if (lineStart && c == QLatin1Char('#')) { // a directive, with its continuation lines
            while (i < n &&
                   !(text.at(i) == QLatin1Char('\n') && text.at(i - 1) != QLatin1Char('\\')))
                ++i;
            out += QLatin1Char('\n');
            continue;
        }
        if (!c.isSpace())
            lineStart = false;
        if (c == QLatin1Char('\n'))
            lineStart = true;
        if (c == QLatin1Char('/') && next == QLatin1Char('/')) {
            while (i < n && text.at(i) != QLatin1Char('\n'))
                ++i;
            out += QLatin1Char('\n');
            lineStart = true;
        } else if (c == QLatin1Char('/') && next == QLatin1Char('*')) {
            const int end = int(text.indexOf(QLatin1String("*/"), i + 2));
            i = end < 0 ? n : end + 1;
            out += QLatin1Char(' ');
        } else if (c == QLatin1Char('R') && next == QLatin1Char('"') &&
                   (i == 0 || !text.at(i - 1).isLetterOrNumber())) {
            const int open = int(text.indexOf(QLatin1Char('('), i + 2));
            const QString close =
                QLatin1Char(')') + text.mid(i + 2, open - i - 2) + QLatin1Char('"');
            const int end = open < 0 ? -1 : int(text.indexOf(close, open));
            i = end < 0 ? n : end + int(close.size()) - 1;
            out += QLatin1String("\"\"");
        } else if (c == QLatin1Char('"') ||
                   (c == QLatin1Char('\'') && !(i > 0 && text.at(i - 1).isLetterOrNumber()))) {
            // (a ' between digits is a digit separator, not a character literal)
            int j = i + 1;
            while (j < n && text.at(j) != c) {
                if (text.at(j) == QLatin1Char('\\'))
                    ++j;
                ++j;
            }
            i = j;
            out += QLatin1String("\"\"");
        } else {
            out += c;
        }
    }
    return out;
}

// The tokens of a statement before its `{` without what does not name the entity: a template's
// parameter list and macro invocations in front (Q_DECLARE_METATYPE(X) has no semicolon).
QStringList declarationTokens(QStringList s)
{
    auto skipBalanced = [&s](int from, const QString& open, const QString& close) {
        int depth = 0;
        for (int i = from; i < s.size(); ++i) {
            depth += s.at(i) == open ? 1 : s.at(i) == close ? -1 : 0;
            if (depth == 0)
                return i + 1;
        }
        return int(s.size());
    };
    static const QRegularExpression macroName(QStringLiteral("^[A-Z][A-Z0-9_]+$"));
    while (s.size() > 1 && macroName.match(s.first()).hasMatch() && s.at(1) == QLatin1String("("))
        s = s.mid(skipBalanced(1, QStringLiteral("("), QStringLiteral(")")));
    if (!s.isEmpty() && s.first() == QLatin1String("template") && s.size() > 1)
        s = QStringList{s.first()} +
            s.mid(skipBalanced(1, QStringLiteral("<"), QStringLiteral(">")));
    return s;
}

// What a definition at file scope outside anonymous namespaces shares with the other files of
// its program: "class X" (a class's member functions defined in it are inline), "function f"
// (inline, constexpr and template functions); empty for anything else.
QString sharedEntity(const QStringList& statement)
{
    const QStringList s = declarationTokens(statement);
    int classAt = -1;
    for (int i = 0; i < s.size(); ++i)
        if (s.at(i) == QLatin1String("class") || s.at(i) == QLatin1String("struct"))
            classAt = i;
    const int firstParen = int(s.indexOf(QLatin1String("(")));
    const bool isEnum = s.contains(QLatin1String("enum"));
    if (classAt >= 0 && !isEnum && int(s.lastIndexOf(QLatin1String("("))) < classAt &&
        classAt + 1 < s.size())
        return QLatin1String("class ") + s.at(classAt + 1);
    if (classAt < 0 && !isEnum && firstParen > 0 && !s.contains(QLatin1String("static")) &&
        !s.at(firstParen - 1).contains(QLatin1String("::")) &&
        (s.first() == QLatin1String("template") ||
         s.mid(0, firstParen).contains(QLatin1String("inline")) ||
         s.mid(0, firstParen).contains(QLatin1String("constexpr"))))
        return QLatin1String("function ") + s.at(firstParen - 1);
    return {};
}

// The entities a file defines that the linker would share with other files (sharedEntity),
// qualified by the named namespaces around them.
QStringList sharedDefinitions(const QString& code)
{
    static const QRegularExpression token(QStringLiteral(R"([A-Za-z_]\w*(?:::[A-Za-z_]\w*)*|\S)"));
    enum class Scope { Named, Anonymous, Other };
    QVector<Scope> scopes;
    QStringList namedPath;
    QStringList statement; // the tokens since the last ; { or }
    QStringList found;
    auto it = token.globalMatch(code);
    while (it.hasNext()) {
        const QString t = it.next().captured();
        if (t == QLatin1String("{")) {
            Scope scope = Scope::Other;
            if (!statement.isEmpty() && statement.first() == QLatin1String("namespace")) {
                scope = statement.size() == 1 ? Scope::Anonymous : Scope::Named;
                if (scope == Scope::Named)
                    namedPath << statement.at(1);
            } else if (!statement.isEmpty() &&
                       std::all_of(scopes.cbegin(), scopes.cend(),
                                   [](Scope s) { return s == Scope::Named; })) {
                const QString entity = sharedEntity(statement);
                const int space = int(entity.indexOf(QLatin1Char(' ')));
                if (!entity.isEmpty())
                    found << entity.left(space + 1) +
                                 (namedPath + QStringList{entity.mid(space + 1)})
                                     .join(QLatin1String("::"));
            }
            scopes << scope;
            statement.clear();
        } else if (t == QLatin1String("}")) {
            if (!scopes.isEmpty() && scopes.takeLast() == Scope::Named && !namedPath.isEmpty())
                namedPath.removeLast();
            statement.clear();
        } else if (t == QLatin1String(";")) {
            statement.clear();
        } else {
            statement << t;
        }
    }
    return found;
}

} // namespace

class TestTestSourceNames : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void sharedDefinitions_foundWhereTheLinkerSharesThem_data();
    void sharedDefinitions_foundWhereTheLinkerSharesThem();
    void testFiles_noSharedDefinitionTwice();
};

void TestTestSourceNames::sharedDefinitions_foundWhereTheLinkerSharesThem_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("class at file scope")
        << "struct Rig { int f() { return 1; } };" << QStringList{"class Rig"};
    QTest::newRow("in an anonymous namespace")
        << "namespace { struct Rig {}; inline int f() {} }" << QStringList{};
    QTest::newRow("in a named namespace")
        << "namespace a::b { class Bench : public QObject { void g() {} }; }"
        << QStringList{"class a::b::Bench"};
    QTest::newRow("inline, constexpr and template functions")
        << "inline int f(int x) { return x; } constexpr double g() { return 1; }\n"
           "template <typename T> T h(T t) { return t; } int plain() { return 0; }\n"
           "static inline int s() { return 0; }"
        << QStringList{"function f", "function g", "function h"};
    QTest::newRow("a template's class parameter, a macro in front")
        << "template <class T> T pick(T a) { return a; }\n"
           "Q_DECLARE_METATYPE(Foo) struct Bar {};"
        << QStringList{"function pick", "class Bar"};
    QTest::newRow("members, declarations, enums, lambdas are not")
        << "class T; void TestX::run() { struct Local {}; auto l = [] { return 1; }; }\n"
           "enum class Mode { A }; int TestX::f() const { return 0; }"
        << QStringList{};
    QTest::newRow("comments, strings, raw strings and directives")
        << "// struct A {\n/* class B { */ const char* s = \"struct C {\";\n"
           "const char* r = R\"x(struct D { } )x\";\n#define E struct E {\nstruct F {};"
        << QStringList{"class F"};
}

void TestTestSourceNames::sharedDefinitions_foundWhereTheLinkerSharesThem()
{
    QFETCH(QString, source);
    QFETCH(QStringList, expected);
    QCOMPARE(sharedDefinitions(codeOnly(source)), expected);
}

void TestTestSourceNames::testFiles_noSharedDefinitionTwice()
{
    QMap<QString, QStringList> filesOf;
    int files = 0;
    QDirIterator it(QStringLiteral(STEPDECK_SOURCE_DIR "/tests"), {QStringLiteral("*.cpp")},
                    QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        if (path.contains(QLatin1String("/tests/fuzz/"))) // built on their own, never grouped
            continue;
        QFile file(path);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(path));
        ++files;
        const QString code = codeOnly(QString::fromUtf8(file.readAll()));
        QStringList names = sharedDefinitions(code);
        names.removeDuplicates(); // a file may reopen its own namespace
        for (const QString& name : names)
            filesOf[name] << path.mid(int(qstrlen(STEPDECK_SOURCE_DIR)) + 1);
    }
    QVERIFY2(files > 150, qPrintable(QStringLiteral("only %1 test files found").arg(files)));
    QStringList twice;
    for (auto e = filesOf.cbegin(); e != filesOf.cend(); ++e)
        if (e.value().size() > 1)
            twice << e.key() + QLatin1String(": ") + e.value().join(QLatin1String(", "));
    QVERIFY2(twice.isEmpty(),
             qPrintable(QLatin1String("defined at file scope in several test files (move them "
                                      "into an anonymous namespace or rename them):\n") +
                        twice.join(QLatin1Char('\n'))));
}

STEPDECK_TEST_GUILESS_MAIN(TestTestSourceNames)
#include "tst_testsourcenames.moc"
