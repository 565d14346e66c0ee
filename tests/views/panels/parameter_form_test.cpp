// The form builder on real drivers' declarations: the simulated hammer
// station's and tyre tester's parameter specs give one field of the right kind
// per parameter, with the spec's unit, range, default and help; values make the
// round trip; a value out of range is clamped to the bound with the reason shown
// next to its field; a refused choice keeps the old value and says why.
#include "views/panels/parameter_form.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QtTest>

#include <set>

// Drivers through the registry: devices/sim/sim_drivers.h reaches
// threaded_device.h, whose emit() collides with Qt's emit macro.
#include "devices/common/driver.h"
#include "views/panels/parameter_texts.h"

using mozzi::devices::ParameterMap;
using mozzi::devices::ParameterSpec;
using mozzi::devices::ParameterType;
using mozzi::views::ParameterForm;

namespace {

std::vector<ParameterSpec> specsOf(const char* key) {
  mozzi::devices::Driver* driver = mozzi::devices::builtinDrivers().find(key);
  if (!driver) qFatal("no driver %s", key);
  auto device = driver->create(mozzi::devices::DeviceDescriptor{key, "", 0, 0, "", "sim:0"});
  if (!device.ok()) qFatal("cannot create %s: %s", key, device.error().describe().c_str());
  return (*device)->capabilities().parameters;
}

const ParameterSpec& spec(const std::vector<ParameterSpec>& specs, const std::string& key) {
  for (const auto& s : specs) {
    if (s.key == key) return s;
  }
  qFatal("no parameter %s", key.c_str());
}

}  // namespace

class ParameterFormTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    hammer_ = specsOf("sim-hammer");
    tyre_ = specsOf("sim-tyre-tester");
    QVERIFY(hammer_.size() >= 8);
  }

  void oneFieldOfTheRightKindPerParameter() {
    ParameterForm form(hammer_);
    for (const auto& s : hammer_) {
      QWidget* editor = form.editor(s.key);
      QVERIFY2(editor, s.key.c_str());
      QCOMPARE(editor->toolTip(), QString::fromStdString(s.help));  // no translator loaded: the English help
      switch (s.type) {
        case ParameterType::Bool: QVERIFY2(qobject_cast<QCheckBox*>(editor), s.key.c_str()); break;
        case ParameterType::Integer:
          QVERIFY2(qobject_cast<QSpinBox*>(editor) || qobject_cast<QDoubleSpinBox*>(editor), s.key.c_str());
          break;
        case ParameterType::Real: QVERIFY2(qobject_cast<QDoubleSpinBox*>(editor), s.key.c_str()); break;
        case ParameterType::Choice: {
          auto* box = qobject_cast<QComboBox*>(editor);
          QVERIFY2(box, s.key.c_str());
          QCOMPARE(box->count(), static_cast<int>(s.choices.size()));
          break;
        }
        case ParameterType::Text: QVERIFY2(qobject_cast<QLineEdit*>(editor), s.key.c_str()); break;
      }
    }
    // Peak force: N, 1..4000 N as the driver declares, default 200 N.
    const auto& peak = spec(hammer_, "hammer.peak_force");
    auto* box = qobject_cast<QDoubleSpinBox*>(form.editor("hammer.peak_force"));
    QCOMPARE(box->suffix(), QStringLiteral(" N"));
    QCOMPARE(box->minimum(), *peak.min);
    QCOMPARE(box->maximum(), *peak.max);
    QCOMPARE(box->value(), std::get<double>(peak.defaultValue));
    // Decimals follow the magnitudes: 200 N -> 2; 0.002 m/s^2 noise -> 5.
    QCOMPARE(box->decimals(), 2);
    auto* noise = qobject_cast<QDoubleSpinBox*>(form.editor("noise.response_rms"));
    QCOMPARE(noise->decimals(), mozzi::views::parameterDecimals(spec(hammer_, "noise.response_rms")));
    QCOMPARE(noise->decimals(), 5);
    QCOMPARE(noise->value(), 0.002);
    // The label is the spec's label, its buddy the field.
    auto* rows = qobject_cast<QFormLayout*>(form.layout());
    QVERIFY(rows);
    QCOMPARE(rows->rowCount(), static_cast<int>(hammer_.size()));
    auto* label = qobject_cast<QLabel*>(rows->itemAt(0, QFormLayout::LabelRole)->widget());
    QVERIFY(label);
    QCOMPARE(label->text(), QString::fromStdString(hammer_.front().label));
    QCOMPARE(label->buddy(), form.editor(hammer_.front().key));
  }

  void defaultsAreWhatTheDriverApplies() {
    ParameterForm form(hammer_);
    auto applied = mozzi::devices::applyParameters(hammer_, {});
    QVERIFY(applied.ok());
    QCOMPARE(form.values(), *applied);
    QVERIFY(!form.hasProblems());
  }

  void valuesMakeTheRoundTrip() {
    ParameterForm form(hammer_);
    QSignalSpy changed(&form, &ParameterForm::valuesChanged);
    ParameterMap in = form.values();
    in["hammer.tip"] = std::string("rubber");
    in["hammer.peak_force"] = 350.25;
    in["noise.response_rms"] = 0.01234;
    in["sim.seed"] = std::int64_t{4000000000};  // past 2^31: the seed range is 32-bit unsigned
    in["sim.realtime"] = false;
    QVERIFY(form.setValues(in).ok());
    QCOMPARE(changed.count(), 1);  // once for the whole map
    QCOMPARE(form.values(), in);
    // What the form gives, the driver accepts as it is.
    auto applied = mozzi::devices::applyParameters(hammer_, form.values());
    QVERIFY2(applied.ok(), applied.ok() ? "" : applied.error().describe().c_str());
    QCOMPARE(*applied, in);

    // Text and integers of the tyre tester.
    ParameterForm tyre(tyre_);
    ParameterMap t = tyre.values();
    t["yaw.frequencies_hz"] = std::string("0.5,1,2");
    t["yaw.cycles"] = std::int64_t{12};
    QVERIFY(tyre.setValues(t).ok());
    QCOMPARE(tyre.values(), t);
  }

  void outOfRangeIsClampedAndSaysWhy() {
    ParameterForm form(hammer_);
    form.resize(600, 900);
    auto r = form.setValues({{"hammer.peak_force", 1.0e6}, {"hammer.interval_s", 0.001}});
    QVERIFY(!r.ok());
    QCOMPARE(QString::fromStdString(r.error().where), QStringLiteral("parameter hammer.peak_force"));
    QCOMPARE(std::get<double>(form.values().at("hammer.peak_force")), 4000.0);  // the declared maximum
    QCOMPARE(std::get<double>(form.values().at("hammer.interval_s")), 0.05);    // the declared minimum
    const QString why = form.problem("hammer.peak_force");
    QVERIFY2(why.contains(QStringLiteral("1000000")) && why.contains(QStringLiteral("4000")), qPrintable(why));
    auto* problem = form.findChild<QLabel*>(QStringLiteral("hammer.peak_force.problem"));
    QVERIFY(problem);
    QVERIFY(!problem->isHidden());
    QVERIFY(form.hasProblems());
    saveScreenshot(form, QStringLiteral("parameter_form.png"));

    // A choice the driver does not offer: the old value stays.
    QVERIFY(!form.setValues({{"hammer.tip", std::string("wood")}}).ok());
    QCOMPARE(std::get<std::string>(form.values().at("hammer.tip")), std::string("plastic"));
    QVERIFY(form.problem("hammer.tip").contains(QStringLiteral("wood")));

    // The user edits the field: the message goes.
    QSignalSpy changed(&form, &ParameterForm::valuesChanged);
    qobject_cast<QDoubleSpinBox*>(form.editor("hammer.peak_force"))->setValue(500.0);
    QCOMPARE(changed.count(), 1);
    QVERIFY(form.problem("hammer.peak_force").isEmpty());
    QVERIFY(problem->isHidden());
    form.resetToDefaults();
    QVERIFY(!form.hasProblems());
  }

  // Labels and help come from devices/ (no Qt): parameter_texts.cpp lists them
  // for lupdate. Every built-in driver that can be created without hardware
  // must have all its texts there, or the Italian form would show English.
  void everyBuiltinParameterTextIsListedForTranslation() {
    std::set<std::string> listed;
    for (const char* text : mozzi::views::parameterTexts()) listed.insert(text);
    QStringList missing;
    int checkedDrivers = 0;
    for (mozzi::devices::Driver* driver : mozzi::devices::builtinDrivers().drivers()) {
      auto device = driver->create(mozzi::devices::DeviceDescriptor{driver->name(), "", 0, 0, "", "sim:0"});
      if (!device.ok()) {
        qInfo("not checked (needs its hardware or a file): %s: %s", driver->name().c_str(),
              device.error().describe().c_str());
        continue;
      }
      ++checkedDrivers;
      for (const auto& s : (*device)->capabilities().parameters) {
        for (const std::string& text : {s.label, s.help}) {
          if (!text.empty() && !listed.count(text))
            missing << QStringLiteral("QT_TRANSLATE_NOOP(\"Parameters\", \"%1\"),").arg(QString::fromStdString(text));
        }
      }
    }
    QVERIFY2(checkedDrivers >= 3, qPrintable(QString::number(checkedDrivers)));
    missing.removeDuplicates();
    QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("add to views/panels/parameter_texts.cpp:\n") +
                                           missing.join(QLatin1Char('\n'))));
  }

 private:
  static void saveScreenshot(QWidget& widget, const QString& name) {
    const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR");
    if (folder.isEmpty()) return;
    QDir().mkpath(folder);
    widget.show();
    QVERIFY(QTest::qWaitForWindowExposed(&widget));
    QVERIFY(widget.grab().save(QDir(folder).filePath(name)));
  }

  std::vector<ParameterSpec> hammer_;
  std::vector<ParameterSpec> tyre_;
};

QTEST_MAIN(ParameterFormTest)
#include "parameter_form_test.moc"
