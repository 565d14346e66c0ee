// The project store's statement helpers (core/io/project_sql.h): run(),
// insert() and single() return Result, and a failure names the statement and
// where it happened, with SQLite's own message.
#include "core/io/project_sql.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <string>

namespace mozzi::core::io::sql {
namespace {

class ProjectSql : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(sqlite3_open(":memory:", &db_), SQLITE_OK);
    ASSERT_TRUE(exec(db_, "CREATE TABLE item(id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE)", "test").ok());
  }
  void TearDown() override { sqlite3_close(db_); }
  sqlite3* db_ = nullptr;
};

TEST_F(ProjectSql, InsertGivesTheNewRowid) {
  Statement stmt(db_, "INSERT INTO item(name) VALUES (?1)");
  auto first = stmt.bind(1, std::string("a")).insert("cannot store item a", "test.mozzi");
  ASSERT_TRUE(first.ok()) << first.error().describe();
  stmt.reset();
  auto second = stmt.bind(1, std::string("b")).insert("cannot store item b", "test.mozzi");
  ASSERT_TRUE(second.ok()) << second.error().describe();
  // A fresh table numbers its rows 1, 2, ... (SQLite's rowid rule).
  EXPECT_EQ(*first, 1);
  EXPECT_EQ(*second, 2);
}

TEST_F(ProjectSql, AFailedRunNamesTheStatementAndWhere) {
  Statement insert(db_, "INSERT INTO item(name) VALUES (?1)");
  ASSERT_TRUE(insert.bind(1, std::string("a")).run("cannot store item a", "test.mozzi").ok());
  insert.reset();
  auto again = insert.bind(1, std::string("a")).run("cannot store item a", "test.mozzi, item a");
  ASSERT_FALSE(again.ok());
  // A constraint is the caller's mistake (sqliteError's mapping).
  EXPECT_EQ(again.error().code, ErrorCode::InvalidArgument);
  EXPECT_EQ(again.error().message.rfind("cannot store item a: ", 0), 0u) << again.error().message;
  EXPECT_NE(again.error().message.find("UNIQUE"), std::string::npos) << again.error().message;
  EXPECT_EQ(again.error().where, "test.mozzi, item a");

  // A statement that does not prepare (no such table) fails at run() too,
  // named the same way, instead of being stepped blindly.
  Statement broken(db_, "INSERT INTO nothing(name) VALUES ('x')");
  EXPECT_FALSE(broken.ok());
  auto r = broken.insert("cannot store into nothing", "test.mozzi");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message.rfind("cannot store into nothing: ", 0), 0u) << r.error().message;
}

TEST_F(ProjectSql, SingleFindsTheRowOrSaysWhatIsAbsent) {
  ASSERT_TRUE(exec(db_, "INSERT INTO item(name) VALUES ('a')", "test").ok());
  Statement found(db_, "SELECT name FROM item WHERE id = ?1");
  ASSERT_TRUE(found.bind(1, std::int64_t{1}).single("cannot read item 1", "no such item", "test.mozzi").ok());
  EXPECT_EQ(columnText(found.get(), 0), "a");

  Statement missing(db_, "SELECT name FROM item WHERE id = ?1");
  auto r = missing.bind(1, std::int64_t{7}).single("cannot read item 7", "no such item", "test.mozzi, item 7");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::NotFound);
  EXPECT_EQ(r.error().message, "no such item");
  EXPECT_EQ(r.error().where, "test.mozzi, item 7");
}

}  // namespace
}  // namespace mozzi::core::io::sql
