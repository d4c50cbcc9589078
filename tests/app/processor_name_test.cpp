/// `ffp bench` names the processor its times were taken on.
#include <sstream>

#include <catch2/catch.hpp>

#include "drivers/app/processor_name.hpp"

using namespace ffp;

TEST_CASE("app: the processor's name is the first model name of /proc/cpuinfo, trimmed") {
  std::istringstream cpuinfo(
      "processor\t: 0\nvendor_id\t: AuthenticAMD\ncpu family\t: 26\nmodel\t\t: 2\n"
      "model name\t: AMD EPYC  \nstepping\t: 1\n\nprocessor\t: 1\nmodel name\t: Another One\n");
  CHECK(processor_name(cpuinfo) == "AMD EPYC");
}

TEST_CASE("app: a cpuinfo text without a model name gives an unknown processor") {
  std::istringstream no_model("processor\t: 0\nmodel\t\t: 2\nmodel name\t:   \n");
  CHECK(processor_name(no_model) == "unknown processor");
  std::istringstream empty;
  CHECK(processor_name(empty) == "unknown processor");
}
