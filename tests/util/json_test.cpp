// JSON's one set of rules (util/json.h): non-finite numbers as "nan",
// "inf" and "-inf" and back; \u escapes read as UTF-8; text that is not
// UTF-8 written with U+FFFD, never thrown; bad JSON an error, never thrown.
#include "util/json.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

namespace glimmer {
namespace {

TEST(Json, NonFiniteNumbersAreStringsAndReadBack) {
    Json j;
    j["nan"] = jsonNumber(NAN);
    j["inf"] = jsonNumber(INFINITY);
    j["minus_inf"] = jsonNumber(-INFINITY);
    j["plain"] = jsonNumber(0.25);
    j["rounded"] = jsonNumber(-INFINITY, 6);
    const std::string line = jsonLine(j);
    EXPECT_EQ(line, R"({"nan":"nan","inf":"inf","minus_inf":"-inf","plain":0.25,"rounded":"-inf"})");
    Json back;
    std::string error;
    ASSERT_TRUE(parseJson(line, back, error)) << error;
    double v = 0;
    ASSERT_TRUE(numberFromJson(back["nan"], v));
    EXPECT_TRUE(std::isnan(v));
    ASSERT_TRUE(numberFromJson(back["inf"], v));
    EXPECT_EQ(v, INFINITY);
    ASSERT_TRUE(numberFromJson(back["minus_inf"], v));
    EXPECT_EQ(v, -INFINITY);
    ASSERT_TRUE(numberFromJson(back["plain"], v));
    EXPECT_EQ(v, 0.25);
    // Any other string, null or an object is not a number; `v` stays.
    v = 7;
    for (const char* other : {R"("NaN")", R"("infinity")", R"("1")", "null", "{}", "true"})
        EXPECT_FALSE(numberFromJson(Json::parse(other), v)) << other;
    EXPECT_EQ(v, 7);
}

TEST(Json, RoundedNumbersWriteTheirShortText) {
    EXPECT_EQ(jsonLine(jsonNumber(0.91234512345678, 6)), "0.912345");
    EXPECT_EQ(jsonLine(jsonNumber(86.029412345, 6)), "86.0294");
    EXPECT_EQ(jsonLine(jsonNumber(4.99492123e-05, 6)), "4.99492e-05");
    EXPECT_EQ(jsonLine(jsonNumber(1.0 / 3)), "0.3333333333333333");  // exact: the shortest that reads back
}

TEST(Json, UnicodeEscapesReadAsUtf8) {
    Json j;
    std::string error;
    ASSERT_TRUE(parseJson(R"({"name": "J\u00fcrgen", "emoji": "\ud83d\ude00", "han": "\u674e\u96f7"})", j, error))
        << error;
    EXPECT_EQ(j["name"], "J\xC3\xBCrgen");  // Jürgen
    EXPECT_EQ(j["emoji"], "\xF0\x9F\x98\x80");
    EXPECT_EQ(j["han"], "\xE6\x9D\x8E\xE9\x9B\xB7");  // 李雷
    // Written back as UTF-8 as it is, control characters escaped.
    EXPECT_EQ(jsonLine(Json("J\xC3\xBCrgen\t\"x\"\n\x01")), "\"J\xC3\xBCrgen\\t\\\"x\\\"\\n\\u0001\"");
}

TEST(Json, TextThatIsNotUtf8IsWrittenWithReplacementCharacters) {
    const std::string latin1 = "J\xFCrgen", cut = "ab\xE6\x9D";  // Latin-1 ü; a character cut short
    std::string line;
    ASSERT_NO_THROW(line = jsonLine(Json{{"name", latin1}, {"cut", cut}}));
    EXPECT_EQ(line, "{\"name\":\"J\xEF\xBF\xBDrgen\",\"cut\":\"ab\xEF\xBF\xBD\"}");
    ASSERT_NO_THROW(line = jsonDocument(Json{{"name", latin1}}));
    EXPECT_EQ(line, "{\n  \"name\": \"J\xEF\xBF\xBDrgen\"\n}\n");
    // What was written reads back; bytes that are not UTF-8 never do.
    Json back;
    std::string error;
    EXPECT_TRUE(parseJson(jsonLine(Json(latin1)), back, error)) << error;
    EXPECT_FALSE(parseJson("\"" + latin1 + "\"", back, error));
    EXPECT_NE(error.find("ill-formed UTF-8"), std::string::npos) << error;
}

TEST(Json, BadJsonIsAnErrorNotAnException) {
    Json j;
    std::string error;
    EXPECT_FALSE(parseJson(R"({"student": "x", "su)", j, error));
    EXPECT_EQ(error.rfind("at column 21: syntax error while parsing object key", 0), 0u) << error;
    EXPECT_FALSE(parseJson("", j, error));
    EXPECT_FALSE(parseJson("{} {}", j, error));
    EXPECT_FALSE(parseJson("[1e400]", j, error));
    EXPECT_NE(error.find("number overflow"), std::string::npos) << error;
    EXPECT_FALSE(parseJson("{\n\"a\": ,}", j, error));
    EXPECT_EQ(error.rfind("at line 2, column 6: syntax error while parsing value - unexpected ','", 0), 0u) << error;
    // Deep nesting is no stack overflow.
    EXPECT_TRUE(parseJson(std::string(100000, '[') + std::string(100000, ']'), j, error)) << error;
}

}  // namespace
}  // namespace glimmer
