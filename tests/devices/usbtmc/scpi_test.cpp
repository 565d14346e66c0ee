// SCPI session over a message channel: the IEEE 488.2 *IDN? fields, the SCPI
// error-queue format (<code>,"<text>"), and errors that name the command.
// The instrument is the generator model of scpi_generator_model.h.
#include "devices/usbtmc/scpi.h"

#include <gtest/gtest.h>

#include "scpi_generator_model.h"

namespace mozzi::devices::usbtmc {
namespace {

using devices::testing::ModelChannel;
using devices::testing::ScpiGeneratorModel;

TEST(Scpi, IdentityHasFourFields) {
  auto id = parseIdentity("Rigol Technologies,DG1022Z,DG1ZA000000001,00.01.12\n");
  ASSERT_TRUE(id.ok()) << id.error().describe();
  EXPECT_EQ(id->manufacturer, "Rigol Technologies");
  EXPECT_EQ(id->model, "DG1022Z");
  EXPECT_EQ(id->serial, "DG1ZA000000001");
  EXPECT_EQ(id->firmware, "00.01.12");
  auto three = parseIdentity("A,B,C");
  ASSERT_FALSE(three.ok());
  EXPECT_NE(three.error().message.find("has 3 fields"), std::string::npos);
  EXPECT_FALSE(parseIdentity("").ok());
}

TEST(Scpi, ErrorQueueEntries) {
  auto e = parseScpiError("-222,\"Data out of range\"\n");
  ASSERT_TRUE(e.ok());
  EXPECT_EQ(e->code, -222);
  EXPECT_EQ(e->message, "Data out of range");
  auto none = parseScpiError("+0,\"No error\"");
  ASSERT_TRUE(none.ok());
  EXPECT_EQ(none->code, 0);
  auto bare = parseScpiError("0");  // some instruments send only the number
  ASSERT_TRUE(bare.ok());
  EXPECT_EQ(bare->code, 0);
  EXPECT_FALSE(parseScpiError("\"No error\"").ok());
  EXPECT_FALSE(parseScpiError("99999999999999999999,\"x\"").ok());
}

TEST(Scpi, Numbers) {
  EXPECT_DOUBLE_EQ(*parseScpiNumber("+1.00000000000000E+01\n", "FREQ?"), 10.0);
  EXPECT_DOUBLE_EQ(*parseScpiNumber(" -2.5 ", "X?"), -2.5);
  auto bad = parseScpiNumber("SIN", "SOUR1:FREQ?");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().where, "SOUR1:FREQ?");
  EXPECT_FALSE(parseScpiNumber("nan", "X?").ok());
  EXPECT_FALSE(parseScpiNumber("9.9E+999", "X?").ok());  // overflow to inf
}

TEST(Scpi, SessionQueriesAndCommonCommands) {
  ScpiGeneratorModel model;
  ModelChannel channel(model);
  ScpiSession s(channel);
  auto id = s.identify();
  ASSERT_TRUE(id.ok()) << id.error().describe();
  EXPECT_EQ(id->model, "33522B");
  model.channels[1].frequency = 123.0;
  ASSERT_TRUE(s.reset().ok());
  EXPECT_DOUBLE_EQ(model.channels[1].frequency, 1000.0);
  EXPECT_EQ(model.received, (std::vector<std::string>{"*IDN?", "*RST", "*OPC?"}));
  auto f = s.queryNumber("SOUR1:FREQ?");
  ASSERT_TRUE(f.ok());
  EXPECT_DOUBLE_EQ(*f, 1000.0);
}

TEST(Scpi, RejectedCommandIsNamedWithTheInstrumentsError) {
  ScpiGeneratorModel model;
  ModelChannel channel(model);
  ScpiSession s(channel);
  ASSERT_TRUE(s.command("SOUR1:FREQ 50").ok());
  auto r = s.command("SOUR1:FREQ 1e9");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "the instrument rejected \"SOUR1:FREQ 1e9\": -222, Data out of range");
  EXPECT_EQ(r.error().where, "model");
  // Two errors at once: the first is shown, the count of the rest too, and
  // the queue is left empty.
  ASSERT_TRUE(s.write("BOGUS1").ok());
  auto r2 = s.command("BOGUS2");
  ASSERT_FALSE(r2.ok());
  EXPECT_EQ(r2.error().message, "the instrument rejected \"BOGUS2\": -113, Undefined header (and 1 more)");
  EXPECT_TRUE(model.errors.empty());
}

TEST(Scpi, DrainStopsAtNoErrorAndIsBounded) {
  ScpiGeneratorModel model;
  ModelChannel channel(model);
  ScpiSession s(channel);
  for (int i = 0; i < 3; ++i) model.errors.emplace_back(-100 - i, "e" + std::to_string(i));
  auto e = s.drainErrors();
  ASSERT_TRUE(e.ok());
  ASSERT_EQ(e->size(), 3u);
  EXPECT_EQ((*e)[0].code, -100);
  EXPECT_EQ((*e)[2].message, "e2");
  for (int i = 0; i < 40; ++i) model.errors.emplace_back(-350, "Queue overflow");
  auto bounded = s.drainErrors(32);
  ASSERT_FALSE(bounded.ok());
  EXPECT_NE(bounded.error().message.find("did not empty after 32"), std::string::npos);
}

TEST(Scpi, TimeoutNamesTheQuery) {
  ScpiGeneratorModel model;
  ModelChannel channel(model);
  ScpiSession s(channel, 250);
  auto r = s.query("SILENT?");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "\"SILENT?\": no answer within 250 ms");
}

}  // namespace
}  // namespace mozzi::devices::usbtmc
