#include "urdf_parse.h"

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <mutex>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "gazebo_plugins.h"
#include "gazebo_sensors.h"
#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::io::detail {
namespace {

/// URDF has no capsule; SDFormat (1.8 on) and Drake's URDF parser read
/// <capsule radius="r" length="l"/> in a <geometry>, l the length of its
/// cylinder, and so does this loader. urdfdom refuses the element, so it
/// reads a copy of the text where every capsule is a cylinder with the same
/// attributes, and `capsules` says which collisions were capsules. Returns
/// whether there was one.
bool capsulesAsCylinders(TiXmlElement& robot, CapsuleSet& capsules) {
  bool any = false;
  for (TiXmlElement* link = robot.FirstChildElement("link"); link; link = link->NextSiblingElement("link")) {
    const char* name = link->Attribute("name");
    for (const char* kind : {"collision", "visual"}) {
      std::size_t index = 0;
      for (TiXmlElement* e = link->FirstChildElement(kind); e; e = e->NextSiblingElement(kind), ++index) {
        TiXmlElement* geometry = e->FirstChildElement("geometry");
        TiXmlElement* capsule = geometry != nullptr ? geometry->FirstChildElement("capsule") : nullptr;
        if (capsule == nullptr) continue;
        capsule->SetValue("cylinder");
        any = true;
        if (std::string(kind) == "collision" && name != nullptr) capsules.insert({name, index});
      }
    }
  }
  return any;
}

/// Why the joints do not make a tree: a link that two joints give a parent,
/// or joints that form a cycle (urdfdom leaks such a model's links: their
/// shared pointers hold each other). "" when they make one, or when an
/// attribute is missing (urdfdom says so).
std::string jointProblem(const TiXmlElement& robot) {
  struct Parent {
    std::string link, joint;
  };
  std::map<std::string, Parent> parent_of;  // child link -> its parent link and joint
  for (const TiXmlElement* j = robot.FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    const TiXmlElement* parent = j->FirstChildElement("parent");
    const TiXmlElement* child = j->FirstChildElement("child");
    const char* name = j->Attribute("name");
    if (name == nullptr || parent == nullptr || child == nullptr || parent->Attribute("link") == nullptr ||
        child->Attribute("link") == nullptr) {
      continue;
    }
    const std::string child_link = child->Attribute("link");
    const auto [at, added] = parent_of.insert({child_link, {parent->Attribute("link"), name}});
    if (!added) {
      return "link '" + child_link + "' is the child of two joints, '" + at->second.joint + "' and '" + name +
             "': a URDF is a tree";
    }
  }
  // Each link has at most one parent: walking up from every link either
  // ends at a root or comes back to a link of the same walk (a cycle).
  std::map<std::string, int> seen;  // 1: on the current walk, 2: ends at a root
  for (const auto& [start, unused] : parent_of) {
    std::vector<std::string> walk;
    std::string at = start;
    while (seen[at] == 0) {
      seen[at] = 1;
      walk.push_back(at);
      const auto up = parent_of.find(at);
      if (up == parent_of.end()) break;
      if (seen[up->second.link] == 1) {
        return "joint '" + up->second.joint + "' closes a cycle of joints (at link '" + up->second.link +
               "'): a URDF is a tree";
      }
      at = up->second.link;
    }
    for (const std::string& link : walk) seen[link] = 2;
  }
  return "";
}

/// The numeric attributes of URDF's elements (and of <capsule>), by element.
const std::map<std::string, std::vector<const char*>>& numericAttributes() {
  static const std::map<std::string, std::vector<const char*>> table{
      {"mass", {"value"}},
      {"inertia", {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}},
      {"origin", {"xyz", "rpy"}},
      {"box", {"size"}},
      {"cylinder", {"radius", "length"}},
      {"capsule", {"radius", "length"}},
      {"sphere", {"radius"}},
      {"mesh", {"scale"}},
      {"axis", {"xyz"}},
      {"limit", {"lower", "upper", "effort", "velocity"}},
      {"dynamics", {"damping", "friction"}},
      {"mimic", {"multiplier", "offset"}},
      {"color", {"rgba"}},
  };
  return table;
}

/// Whether `text` is one or more numbers separated by white space, each read whole.
bool numbers(const char* text) {
  bool any = false;
  for (const char* at = text; *at != '\0';) {
    if (std::isspace(static_cast<unsigned char>(*at)) != 0) {
      ++at;
      continue;
    }
    char* end = nullptr;
    std::strtod(at, &end);
    if (end == at || (*end != '\0' && std::isspace(static_cast<unsigned char>(*end)) == 0)) return false;
    any = true;
    at = end;
  }
  return any;
}

/// The first numeric attribute under `top` (a <link> or <joint>) that is not
/// numbers, as "link 'L' <collision> <box size="0.2 0.2 0.2m">: not a number
/// (or list of numbers)", or "". urdfdom would log it and drop the element.
std::string numberProblem(const TiXmlElement& top) {
  const char* kind = top.Value();
  const char* name = top.Attribute("name");
  std::vector<std::pair<const TiXmlElement*, std::string>> todo;  // element, the path to it
  for (const TiXmlElement* e = top.FirstChildElement(); e; e = e->NextSiblingElement()) todo.push_back({e, ""});
  while (!todo.empty()) {
    const auto [e, path] = todo.back();
    todo.pop_back();
    const std::string here = path + "<" + e->Value() + ">";
    const auto attributes = numericAttributes().find(e->Value());
    if (attributes != numericAttributes().end()) {
      for (const char* attribute : attributes->second) {
        const char* value = e->Attribute(attribute);
        if (value == nullptr || numbers(value)) continue;
        return std::string(kind) + " '" + (name ? name : "") + "' " + path + "<" + e->Value() + " " + attribute +
               "=\"" + value + "\">: not a number" + (std::string(attribute) == "value" ? "" : " (or numbers)") +
               " (URDF gives SI units: write none)";
      }
    }
    for (const TiXmlElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) todo.push_back({c, here});
  }
  return "";
}

/// urdfdom's errors while it parses, from console_bridge, which urdfdom
/// logs through: one parse at a time (the handler is the process's).
class ParserErrors : public console_bridge::OutputHandler {
 public:
  ParserErrors() : level_(console_bridge::getLogLevel()) {
    console_bridge::useOutputHandler(this);
    if (level_ > console_bridge::CONSOLE_BRIDGE_LOG_ERROR) {
      console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_ERROR);
    }
  }
  ~ParserErrors() override {
    console_bridge::setLogLevel(level_);
    console_bridge::restorePreviousOutputHandler();
  }
  ParserErrors(const ParserErrors&) = delete;
  ParserErrors& operator=(const ParserErrors&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
  }

  /// One line: where (the link and element urdfdom names), then the first
  /// cause, then the rest.
  std::string summary() const {
    static const std::regex element_of_link(R"(Could not parse (\w+) element for Link \[([^\]]*)\])");
    std::string where;
    for (const std::string& e : errors) {
      std::smatch m;
      if (std::regex_search(e, m, element_of_link)) {
        where = "link '" + m[2].str() + "' <" + m[1].str() + ">: ";
        break;
      }
    }
    std::string line = where + "urdfdom could not read it: " + errors.front();
    for (std::size_t i = 1; i < errors.size(); ++i) line += (i == 1 ? " (then: " : "; ") + errors[i];
    return errors.size() > 1 ? line + ")" : line;
  }

  std::vector<std::string> errors;

 private:
  console_bridge::LogLevel level_;
};

/// The `<gazebo reference="LINK"><mu1>` and `<mu2>` of `robot` (Gazebo's ODE
/// friction along two directions; one coefficient here, the smaller), or
/// the first problem with them.
std::string gazeboFriction(const TiXmlElement& robot, ParsedUrdf& out) {
  for (const TiXmlElement* g = robot.FirstChildElement("gazebo"); g; g = g->NextSiblingElement("gazebo")) {
    const char* reference = g->Attribute("reference");
    if (reference == nullptr) continue;  // the robot's own markup (plugins)
    for (const char* tag : {"mu1", "mu2"}) {
      const TiXmlElement* e = g->FirstChildElement(tag);
      if (e == nullptr) continue;
      // Gazebo's URDF reader takes a value attribute first (PR2's, Husky's <mu1 value="100.0"/>), else the text.
      const char* text = e->Attribute("value") != nullptr ? e->Attribute("value") : e->GetText();
      char* end = nullptr;
      double mu = text != nullptr ? std::strtod(text, &end) : std::nan("");
      const bool read =
          text != nullptr && end != text && std::string(end).find_first_not_of(" \t\r\n") == std::string::npos;
      std::ostringstream what;
      what << "<gazebo reference=\"" << reference << "\"> <" << tag << "> = '" << (text != nullptr ? text : "") << "'";
      if (!read || !(mu >= 0.0)) return what.str() + ": a friction coefficient must be a number >= 0";
      if (mu > core::ranges::kMaxFriction) {
        out.friction_above.push_back(what.str());
        mu = core::ranges::kMaxFriction;
      }
      const auto [at, fresh] = out.surface_friction.emplace(reference, mu);
      if (!fresh) at->second = std::min(at->second, mu);
    }
  }
  return "";
}

/// Whether `e` (under `<gazebo reference>`) only says what Gazebo does
/// anyway, and so what runs here too: `<gravity>` true, `<selfCollide>`,
/// `<turnGravityOff>`, `<kinematic>` and `<static>` false, and
/// `<provideFeedback>` (a joint's wrench, which a force-torque sensor here
/// needs no flag for). Said as skipped, they made a robot's note longer and
/// told of nothing missing (Ridgeback's base_link has `<gravity>true`).
bool onlyGazebosDefault(const TiXmlElement& e) {
  const std::string tag = e.Value();
  std::string text = e.GetText() != nullptr ? e.GetText() : "";
  text.erase(0, text.find_first_not_of(" \t\n\r"));
  text.erase(text.find_last_not_of(" \t\n\r") + 1);
  const bool yes = text == "true" || text == "1", no = text == "false" || text == "0";
  if (tag == "gravity") return yes;
  if (tag == "selfCollide" || tag == "turnGravityOff" || tag == "kinematic" || tag == "static") return no;
  return tag == "provideFeedback";
}

/// What `<gazebo>` and `<transmission>` markup of `robot` nothing here
/// reads, into out.unread_markup (see ParsedUrdf).
void unreadMarkup(const TiXmlElement& robot, ParsedUrdf& out) {
  const auto attribute = [](const TiXmlElement& e, const char* name) {
    const char* value = e.Attribute(name);
    return std::string(value != nullptr ? value : "");
  };
  const auto add = [&out](const std::string& kind, const std::string& name) {
    std::vector<std::string>& names = out.unread_markup[kind];
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  };
  for (const TiXmlElement* g = robot.FirstChildElement("gazebo"); g; g = g->NextSiblingElement("gazebo")) {
    const std::string reference = attribute(*g, "reference");
    for (const TiXmlElement* e = g->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string tag = e->Value();
      if (tag == "mu1" || tag == "mu2" || tag == "material") continue;  // read above; drawing only
      if (onlyGazebosDefault(*e)) continue;
      std::string kind = "<" + tag + ">";
      if (tag == "sensor") {
        kind = "<sensor type=\"" + attribute(*e, "type") + "\">";
        for (const TiXmlElement* p = e->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) {
          kind += " " + attribute(*p, "filename");
        }
      } else if (tag == "plugin") {
        kind = "<plugin> " + attribute(*e, "filename");
        if (isMimicPlugin(attribute(*e, "filename"))) continue;  // the robot's joints, set in parseUrdf
      }
      const std::string name = !reference.empty() ? reference : tag == "plugin" ? attribute(*e, "name") : "the robot";
      if (readsMarkup(*e)) {  // a sensor (gazebo_sensors.h), for a robot
        out.sensor_markup[kind].push_back(name);
        continue;
      }
      add(kind, name);
    }
  }
  // A robot's transmissions are read (io/transmissions.h checks its controllers against them).
  for (const TiXmlElement* t = robot.FirstChildElement("transmission"); t; t = t->NextSiblingElement("transmission")) {
    out.sensor_markup["<transmission>"].push_back(attribute(*t, "name"));
    TransmissionEntry entry{attribute(*t, "name"), {}, {}};
    for (const TiXmlElement* e = t->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string tag = e->Value();
      if (tag != "joint" && tag != "actuator") continue;
      if (tag == "joint") entry.joints.push_back(attribute(*e, "name"));
      for (const TiXmlElement* h = e->FirstChildElement("hardwareInterface"); h;
           h = h->NextSiblingElement("hardwareInterface")) {
        const std::string text = h->GetText() != nullptr ? h->GetText() : "";
        entry.interfaces.push_back(text.substr(text.rfind('/') + 1));  // hardware_interface/X or X
      }
    }
    out.sensors.transmissions.push_back(std::move(entry));
  }
}

std::mutex& parserMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

ParsedUrdf parseUrdf(const std::string& xml) {
  ParsedUrdf out;
  std::string text;  // the capsules rewritten, when there are any
  TiXmlDocument doc;
  doc.Parse(xml.c_str());
  // The element urdfdom reads: the first <robot>, wherever it stands.
  if (TiXmlElement* robot = doc.FirstChildElement("robot"); !doc.Error() && robot != nullptr) {
    std::string problem = jointProblem(*robot);
    for (const TiXmlElement* e = robot->FirstChildElement(); e && problem.empty(); e = e->NextSiblingElement()) {
      if (std::string(e->Value()) == "link" || std::string(e->Value()) == "joint") problem = numberProblem(*e);
    }
    if (problem.empty()) problem = gazeboFriction(*robot, out);
    if (!problem.empty()) throw std::invalid_argument(problem);
    out.sensors = gazeboSensors(*robot, [&out](const std::string& kind, const std::string& name) {
      std::vector<std::string>& names = out.unread_markup[kind];
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    });
    unreadMarkup(*robot, out);  // after: it adds the transmissions to out.sensors
    if (xml.find("capsule") != std::string::npos && capsulesAsCylinders(*robot, out.capsules)) {
      TiXmlPrinter printer;
      doc.Accept(&printer);
      text = printer.CStr();
    }
  }  // text that is not XML: urdfdom says why
  const std::lock_guard<std::mutex> lock(parserMutex());
  ParserErrors errors;
  out.model = urdf::parseURDF(text.empty() ? xml : text);
  if (!out.model) {
    throw std::invalid_argument("not a valid URDF document" +
                                (errors.errors.empty() ? std::string() : ": " + errors.summary()));
  }
  // The mimic-joint plugins as the URDF's <mimic>: Gazebo classic ignores
  // a URDF <mimic> and runs the plugin, so the plugin's wins.
  for (const RobotDevices::Mimic& m : out.sensors.mimics) {
    for (const std::string* name : {&m.follower, &m.leader}) {
      if (out.model->getJoint(*name) == nullptr) {
        throw std::invalid_argument(m.key + ": the robot has no joint '" + *name + "'");
      }
    }
    auto mimic = std::make_shared<urdf::JointMimic>();
    mimic->joint_name = m.leader;
    mimic->multiplier = m.multiplier;
    mimic->offset = m.offset;
    out.model->joints_.at(m.follower)->mimic = mimic;
  }
  if (!errors.errors.empty()) throw std::invalid_argument(errors.summary());
  return out;
}

}  // namespace rigid_body_sim::io::detail
