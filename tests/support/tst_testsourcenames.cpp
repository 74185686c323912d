// The test files' own names (issue 48): the tests of a part of the tree are built into one
// program (tests/CMakeLists.txt, test groups), a directory's files a few at a time as one
// translation unit, and the libraries' files are compiled in such batches too (CMakeLists.txt). Two
// kinds of names then meet without a compiler error:
// - a class, or an inline, constexpr or template function, defined at file scope outside an
//   anonymous namespace in two test files is one entity to the linker: it keeps one definition
//   and one file's test silently runs the other's code;
// - two file-local functions (anonymous namespace, static) of one name and different parameters
//   in one batch are overloads, and a call may take the other file's.
// Same-named file-local classes and variables in one batch break the compile, so they need no
// check. This test reads every such file and names each case.
#include "TestMain.h"
#include <QDirIterator>
#include <QFileInfo>
#include <QMap>
#include <QRegularExpression>
#include <QtTest>

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

// The name of the function a statement before `{` defines, if it defines one that is not a
// member (f in `inline int f(int x) const`); empty for classes, enums, lambdas, initializers.
QString definedFunction(const QStringList& s)
{
    const int firstParen = int(s.indexOf(QLatin1String("(")));
    if (firstParen <= 0 || s.contains(QLatin1String("class")) ||
        s.contains(QLatin1String("struct")) || s.contains(QLatin1String("enum")) ||
        s.mid(0, firstParen).contains(QLatin1String("=")))
        return {};
    const QString name = s.at(firstParen - 1);
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_]\\w*$"));
    static const QStringList notNames{"if", "for", "while", "switch", "return", "catch"};
    return identifier.match(name).hasMatch() && !notNames.contains(name) ? name : QString();
}

struct Definitions
{
    // At file scope outside anonymous namespaces, where the linker shares them with the other
    // files of the program: "class X" (a class's member functions defined in it are inline),
    // "function f" (inline, constexpr and template functions); qualified by the named
    // namespaces around them.
    QStringList shared;
    // Functions of the file's own (in an anonymous namespace, or static): in one batch with
    // another file's function of the same name and other parameters, a call of either may
    // silently take the other as the better overload.
    QStringList local;
};

// What a definition at file scope adds to `out` (see Definitions).
void classify(const QStringList& statement, bool anonymous, const QStringList& namedPath,
              Definitions* out)
{
    const QStringList s = declarationTokens(statement);
    int classAt = -1;
    for (int i = 0; i < s.size(); ++i)
        if (s.at(i) == QLatin1String("class") || s.at(i) == QLatin1String("struct"))
            classAt = i;
    const QString prefix =
        namedPath.isEmpty() ? QString() : namedPath.join(QLatin1String("::")) + QLatin1String("::");
    const QString function = definedFunction(s);
    const bool isStatic = s.contains(QLatin1String("static"));
    if (!function.isEmpty() && (anonymous || isStatic))
        out->local << QLatin1String("function ") + function;
    if (anonymous)
        return;
    if (classAt >= 0 && !s.contains(QLatin1String("enum")) &&
        int(s.lastIndexOf(QLatin1String("("))) < classAt && classAt + 1 < s.size())
        out->shared << QLatin1String("class ") + prefix + s.at(classAt + 1);
    else if (!function.isEmpty() && !isStatic &&
             (s.first() == QLatin1String("template") || s.contains(QLatin1String("inline")) ||
              s.contains(QLatin1String("constexpr"))))
        out->shared << QLatin1String("function ") + prefix + function;
}

// The definitions of a file (see Definitions).
Definitions definitions(const QString& code)
{
    static const QRegularExpression token(QStringLiteral(R"([A-Za-z_]\w*(?:::[A-Za-z_]\w*)*|\S)"));
    enum class Scope { Named, Anonymous, Other };
    QVector<Scope> scopes;
    QStringList namedPath;
    QStringList statement; // the tokens since the last ; { or }
    Definitions found;
    auto it = token.globalMatch(code);
    while (it.hasNext()) {
        const QString t = it.next().captured();
        if (t == QLatin1String("{")) {
            Scope scope = Scope::Other;
            if (!statement.isEmpty() && statement.first() == QLatin1String("namespace")) {
                scope = statement.size() == 1 ? Scope::Anonymous : Scope::Named;
                if (scope == Scope::Named)
                    namedPath << statement.at(1);
            } else if (!statement.isEmpty() && !scopes.contains(Scope::Other)) {
                classify(statement, scopes.contains(Scope::Anonymous), namedPath, &found);
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

// "name: file, file" for each name more than one file defines.
QStringList definedTwice(const QMap<QString, QStringList>& filesOf)
{
    QStringList twice;
    for (auto e = filesOf.cbegin(); e != filesOf.cend(); ++e)
        if (e.value().size() > 1)
            twice << e.key() + QLatin1String(": ") + e.value().join(QLatin1String(", "));
    return twice;
}

} // namespace

class TestTestSourceNames : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void definitions_sharedAndLocalAsTheLinkerAndABatchSeeThem_data();
    void definitions_sharedAndLocalAsTheLinkerAndABatchSeeThem();
    void sourceFiles_noSharedDefinitionTwiceNoLocalFunctionTwiceInADirectory_data();
    void sourceFiles_noSharedDefinitionTwiceNoLocalFunctionTwiceInADirectory();
};

void TestTestSourceNames::definitions_sharedAndLocalAsTheLinkerAndABatchSeeThem_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QStringList>("shared");
    QTest::addColumn<QStringList>("local");
    QTest::newRow("class at file scope")
        << "struct Rig { int f() { return 1; } };" << QStringList{"class Rig"} << QStringList{};
    QTest::newRow("in an anonymous namespace")
        << "namespace { struct Rig {}; inline int f() {} QString g(int a) { return {}; } }"
        << QStringList{} << QStringList{"function f", "function g"};
    QTest::newRow("in a named namespace")
        << "namespace a::b { class Bench : public QObject { void g() {} }; }"
        << QStringList{"class a::b::Bench"} << QStringList{};
    QTest::newRow("inline, constexpr, template and static functions")
        << "inline int f(int x) { return x; } constexpr double g() { return 1; }\n"
           "template <typename T> T h(T t) { return t; } int plain() { return 0; }\n"
           "static inline int s() { return 0; }"
        << QStringList{"function f", "function g", "function h"} << QStringList{"function s"};
    QTest::newRow("a template's class parameter, a macro in front")
        << "template <class T> T pick(T a) { return a; }\n"
           "Q_DECLARE_METATYPE(Foo) struct Bar {};"
        << QStringList{"function pick", "class Bar"} << QStringList{};
    QTest::newRow("members, declarations, enums, lambdas, initializers are not")
        << "class T; void TestX::run() { struct Local {}; auto l = [] { return 1; }; }\n"
           "enum class Mode { A }; int TestX::f() const { return 0; }\n"
           "namespace { const QList<int> kList{1, 2}; const auto v = make(QList<int>{1}); }"
        << QStringList{} << QStringList{};
    QTest::newRow("comments, strings, raw strings and directives")
        << "// struct A {\n/* class B { */ const char* s = \"struct C {\";\n"
           "const char* r = R\"x(struct D { } )x\";\n#define E struct E {\nstruct F {};"
        << QStringList{"class F"} << QStringList{};
}

void TestTestSourceNames::definitions_sharedAndLocalAsTheLinkerAndABatchSeeThem()
{
    QFETCH(QString, source);
    QFETCH(QStringList, shared);
    QFETCH(QStringList, local);
    const Definitions found = definitions(codeOnly(source));
    QCOMPARE(found.shared, shared);
    QCOMPARE(found.local, local);
}

// The files compiled in unity batches, which hold files of one directory (tests/CMakeLists.txt
// and the libraries in CMakeLists.txt): file-local functions of one name are checked within a
// directory, shared definitions over all files of a kind.
void TestTestSourceNames::sourceFiles_noSharedDefinitionTwiceNoLocalFunctionTwiceInADirectory_data()
{
    QTest::addColumn<QStringList>("roots");
    QTest::addColumn<QString>("pattern");
    QTest::addColumn<int>("atLeast");
    QTest::newRow("tests") << QStringList{"tests"} << "tst_*.cpp" << 150;
    QTest::newRow("libraries") << QStringList{"core", "ui", "app/cli"} << "*.cpp" << 300;
}

void TestTestSourceNames::sourceFiles_noSharedDefinitionTwiceNoLocalFunctionTwiceInADirectory()
{
    QFETCH(QStringList, roots);
    QFETCH(QString, pattern);
    QFETCH(int, atLeast);
    QMap<QString, QStringList> sharedIn;
    QMap<QString, QStringList> localIn; // key: directory and name
    int files = 0;
    const QString source = QStringLiteral(STEPDECK_SOURCE_DIR);
    for (const QString& root : std::as_const(roots)) {
        QDirIterator it(source + QLatin1Char('/') + root, {pattern}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            if (path.contains(QLatin1String("/tests/fuzz/"))) // built on their own
                continue;
            QFile file(path);
            QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(path));
            ++files;
            const QString relative = path.mid(source.size() + 1);
            const QString directory = QFileInfo(relative).path();
            Definitions found = definitions(codeOnly(QString::fromUtf8(file.readAll())));
            found.shared.removeDuplicates(); // a file may reopen its own namespace
            found.local.removeDuplicates();  // and overload its own functions
            for (const QString& name : std::as_const(found.shared))
                sharedIn[name] << relative;
            for (const QString& name : std::as_const(found.local))
                localIn[directory + QLatin1String(": ") + name] << relative;
        }
    }
    QVERIFY2(files >= atLeast, qPrintable(QStringLiteral("only %1 files found").arg(files)));
    const QStringList shared = definedTwice(sharedIn);
    QVERIFY2(shared.isEmpty(),
             qPrintable(QLatin1String("defined at file scope in several files (move them into "
                                      "an anonymous namespace or rename them):\n") +
                        shared.join(QLatin1Char('\n'))));
    const QStringList local = definedTwice(localIn);
    QVERIFY2(local.isEmpty(),
             qPrintable(QLatin1String("file-local functions of one name in one directory (a "
                                      "batch may overload one with the other; rename them):\n") +
                        local.join(QLatin1Char('\n'))));
}

STEPDECK_TEST_GUILESS_MAIN(TestTestSourceNames)
#include "tst_testsourcenames.moc"
