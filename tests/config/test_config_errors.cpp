// One TOML snippet per bad value, and the exact message it must give. Most
// snippets start with a good [link] (lines 1-2) so that only the case's own
// line is wrong.
#include <gtest/gtest.h>

#include <string>

#include "config/config.hpp"

namespace kerf::config {
namespace {

#define TCP "[link]\nkind = \"modbus-tcp\"\n"  // lines 1 and 2

struct BadCase {
  const char* name;
  const char* toml;
  const char* message;
};

const BadCase kCases[] = {
    // [machine]
    {"accel_negative", TCP "[machine]\naccel = -5\n",
     "kerf.toml:4: machine.accel: must be > 0, got -5"},
    {"accel_string", TCP "[machine]\naccel = \"fast\"\n",
     "kerf.toml:4: machine.accel: expected a number, got a string"},
    {"max_feed_nan", TCP "[machine]\nmax_feed = nan\n",
     "kerf.toml:4: machine.max_feed: must be a finite number, got nan"},
    {"max_feed_inf", TCP "[machine]\nmax_feed = -inf\n",
     "kerf.toml:4: machine.max_feed: must be a finite number, got -inf"},
    {"jerk_negative", TCP "[machine]\njerk = -0.5\n",
     "kerf.toml:4: machine.jerk: must be >= 0, got -0.5"},
    {"servo_period_too_long", TCP "[machine]\nservo_period = 0.5\n",
     "kerf.toml:4: machine.servo_period: must be in (0, 0.1], got 0.5"},
    {"cycle_zero", TCP "[machine]\ncycle = 0\n",
     "kerf.toml:4: machine.cycle: must be in (0, 0.1], got 0"},
    {"machine_unknown_key", TCP "[machine]\naccel = 100\nacel = 100\n",
     "kerf.toml:5: machine.acel: unknown key"},
    {"machine_not_a_table", "machine = 3\n" TCP,
     "kerf.toml:1: machine: expected a table, got an integer"},
    {"one_axis", TCP "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 10\n",
     "kerf.toml:3: machine.axis: need 2 or 3 axes (x, y, then optionally z), got 1"},
    {"axis_counts_zero",
     TCP "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 10\n[[machine.axis]]\nname = \"y\"\n"
         "counts_per_mm = 0\n",
     "kerf.toml:8: machine.axis[1].counts_per_mm: must be > 0, got 0"},
    {"axis_counts_missing",
     TCP "[[machine.axis]]\nname = \"x\"\n[[machine.axis]]\nname = \"y\"\ncounts_per_mm = 5\n",
     "kerf.toml:3: machine.axis[0].counts_per_mm: missing (drive counts per mm)"},
    {"axis_wrong_name",
     TCP "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 10\n[[machine.axis]]\nname = \"z\"\n"
         "counts_per_mm = 10\n",
     "kerf.toml:7: machine.axis[1].name: expected \"y\" (axes are x, y, then optionally z), got \"z\""},
    {"z_feed_zero",
     TCP "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 10\n[[machine.axis]]\nname = \"y\"\n"
         "counts_per_mm = 10\n[[machine.axis]]\nname = \"z\"\ncounts_per_mm = 10\nfeed = 0\n",
     "kerf.toml:12: machine.axis[2].feed: must be > 0, got 0"},
    {"z_gpio_home_switch",
     TCP "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 10\n[[machine.axis]]\nname = \"y\"\n"
         "counts_per_mm = 10\n[[machine.axis]]\nname = \"z\"\ncounts_per_mm = 10\nhome_input = 3\n",
     "kerf.toml:12: machine.axis[2].home_input: a GPIO home switch homes x or y; z homes on the board's or drive's "
     "own input"},
    {"feed_on_x",
     TCP "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 10\nfeed = 100\n[[machine.axis]]\nname = \"y\"\n"
         "counts_per_mm = 10\n",
     "kerf.toml:6: machine.axis[0].feed: unknown key"},
    {"axis_max_not_above_min",
     TCP "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 10\nmin = 5\nmax = 5\n[[machine.axis]]\nname = \"y\"\n"
         "counts_per_mm = 10\n",
     "kerf.toml:7: machine.axis[0].max: must be > min (5), got 5"},
    {"axis_min_string",
     TCP "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 10\nmin = \"left\"\n[[machine.axis]]\nname = \"y\"\n"
         "counts_per_mm = 10\n",
     "kerf.toml:6: machine.axis[0].min: expected a number, got a string"},
    {"axis_not_tables", TCP "[machine]\naxis = [1, 2]\n",
     "kerf.toml:4: machine.axis[0]: expected a table, got an integer"},
    {"rapid_above_max", TCP "[machine]\nmax_feed = 8000\nrapid_feed = 9000\n",
     "kerf.toml:5: machine.rapid_feed: must be <= machine.max_feed (8000), got 9000"},
    {"min_ferror_above_ferror", TCP "[machine]\nferror = 0.5\nmin_ferror = 0.8\n",
     "kerf.toml:5: machine.min_ferror: machine.min_ferror (0.8) must be <= machine.ferror (0.5)"},
    {"ferror_zero", TCP "[machine]\nferror = 0\n", "kerf.toml:4: machine.ferror: must be > 0, got 0"},
    {"gpio_watchdog_debounce", TCP "[gpio.watchdog]\nname = \"PUMP\"\ndebounce_ms = 5\n",
     "kerf.toml:5: gpio.watchdog.debounce_ms: not for an output"},

    // [link]
    {"link_missing", "[cut]\nfeed = 100\n",
     "kerf.toml:1: link: missing: the machine needs a link ([link] with kind = \"modbus-tcp\", "
     "\"modbus-rtu\" or \"can\")"},
    {"link_kind_missing", "[link]\nhost = \"10.0.0.2\"\n",
     "kerf.toml:1: link.kind: missing (expected modbus-tcp, modbus-rtu or can)"},
    {"link_kind_unknown", "# the board\n\n[link]\nkind = \"modbus-udp\"\n",
     "kerf.toml:4: link.kind: unknown link \"modbus-udp\" (expected modbus-tcp, modbus-rtu or can)"},
    {"link_port_range", TCP "port = 70000\n",
     "kerf.toml:3: link.port: must be in 1..65535, got 70000"},
    {"link_port_float", TCP "port = 502.0\n",
     "kerf.toml:3: link.port: expected an integer, got a floating-point number"},
    {"link_unit_zero", TCP "unit = 0\n", "kerf.toml:3: link.unit: must be in 1..247, got 0"},
    {"link_timeout_negative", TCP "timeout = -1\n",
     "kerf.toml:3: link.timeout: must be > 0, got -1"},
    {"link_key_of_other_kind", TCP "device = \"/dev/ttyUSB0\"\n",
     "kerf.toml:3: link.device: not used by a modbus-tcp link"},
    {"link_host_empty", TCP "host = \"\"\n", "kerf.toml:3: link.host: must not be empty"},
    {"rtu_without_device", "[link]\nkind = \"modbus-rtu\"\nbaud = 9600\n",
     "kerf.toml:2: link.device: required for a modbus-rtu link (e.g. \"/dev/ttyUSB0\")"},
    {"can_without_node_ids", "[link]\nkind = \"can\"\n",
     "kerf.toml:2: link.node_ids: required for a can link: one node id per axis (2 axes)"},
    {"can_node_ids_count", "[link]\nkind = \"can\"\nnode_ids = [1, 2, 3]\n",
     "kerf.toml:3: link.node_ids: need one node id per axis (2 axes, the default x and y), got 3"},
    {"can_node_id_range", "[link]\nkind = \"can\"\nnode_ids = [1, 128]\n",
     "kerf.toml:3: link.node_ids[1]: must be in 1..127, got 128"},
    {"can_node_id_twice", "[link]\nkind = \"can\"\nnode_ids = [4, 4]\n",
     "kerf.toml:3: link.node_ids[1]: node 4 is already link.node_ids[0]"},
    {"can_sync_range", "[link]\nkind = \"can\"\nnode_ids = [1, 2]\nsync_ms = 20\n",
     "kerf.toml:4: link.sync_ms: must be in [1, 10], got 20"},
    {"can_node_ids_not_array", "[link]\nkind = \"can\"\nnode_ids = 1\n",
     "kerf.toml:3: link.node_ids: expected an array of integers, got an integer"},

    // [gpio]
    {"gpio_neither_offset_nor_name", TCP "[gpio]\nchip = \"gpiochip0\"\n[gpio.estop]\nactive_low = true\n",
     "kerf.toml:5: gpio.estop: needs offset (with a chip) or name"},
    {"gpio_offset_and_name", TCP "[gpio.arc_ok]\nchip = \"gpiochip0\"\noffset = 3\nname = \"ARC_OK\"\n",
     "kerf.toml:6: gpio.arc_ok.name: give offset or name, not both"},
    {"gpio_offset_without_chip", TCP "[gpio.hold]\noffset = 3\n",
     "kerf.toml:4: gpio.hold.offset: needs a chip: set gpio.chip or gpio.hold.chip"},
    {"gpio_offset_negative", TCP "[gpio]\nchip = \"gpiochip0\"\n[gpio.torch]\noffset = -1\n",
     "kerf.toml:6: gpio.torch.offset: must be in 0..65535, got -1"},
    {"gpio_active_low_string", TCP "[gpio.estop]\nname = \"ESTOP\"\nactive_low = \"yes\"\n",
     "kerf.toml:5: gpio.estop.active_low: expected a boolean (true or false), got a string"},
    {"gpio_debounce_on_output", TCP "[gpio.torch]\nname = \"TORCH\"\ndebounce_ms = 5\n",
     "kerf.toml:5: gpio.torch.debounce_ms: not for an output"},
    {"gpio_debounce_range", TCP "[gpio.cycle_start]\nname = \"START\"\ndebounce_ms = 5000\n",
     "kerf.toml:5: gpio.cycle_start.debounce_ms: must be in [0, 1000], got 5000"},
    {"gpio_unknown_line", TCP "[gpio.torchh]\nname = \"TORCH\"\n",
     "kerf.toml:3: gpio.torchh: unknown key"},
    {"gpio_duplicate_offset",
     TCP "[gpio]\nchip = \"gpiochip0\"\n[gpio.estop]\noffset = 22\n[[gpio.limit]]\n"
         "chip = \"/dev/gpiochip0\"\noffset = 22\n",
     "kerf.toml:9: gpio.limit[0].offset: line 22 of gpiochip0 is already gpio.estop"},
    {"gpio_duplicate_name", TCP "[gpio.hold]\nname = \"BTN\"\n[gpio.cycle_start]\nname = \"BTN\"\n",
     "kerf.toml:6: gpio.cycle_start.name: line \"BTN\" on any chip is already gpio.hold"},
    {"gpio_too_many_limits",
     TCP "[[gpio.limit]]\nname = \"L0\"\n[[gpio.limit]]\nname = \"L1\"\n[[gpio.limit]]\nname = \"L2\"\n"
         "[[gpio.limit]]\nname = \"L3\"\n[[gpio.limit]]\nname = \"L4\"\n[[gpio.limit]]\nname = \"L5\"\n"
         "[[gpio.limit]]\nname = \"L6\"\n[[gpio.limit]]\nname = \"L7\"\n[[gpio.limit]]\nname = \"L8\"\n",
     "kerf.toml:19: gpio.limit: at most 8 limit lines, got 9"},
    {"gpio_limit_unknown_key", TCP "[[gpio.limit]]\nname = \"XLIM\"\nactve_low = true\n",
     "kerf.toml:5: gpio.limit[0].actve_low: unknown key"},
    {"gpio_output_no_number", TCP "[[gpio.output]]\nname = \"MARKER\"\n",
     "kerf.toml:3: gpio.output[0]: needs number (the M62..M65 P number)"},
    {"gpio_input_number_range", TCP "[[gpio.input]]\nname = \"FLOAT\"\nnumber = 300\n",
     "kerf.toml:5: gpio.input[0].number: must be in 0..255, got 300"},
    {"gpio_output_number_twice",
     TCP "[[gpio.output]]\nnumber = 2\nname = \"A\"\n[[gpio.output]]\nnumber = 2\nname = \"B\"\n",
     "kerf.toml:7: gpio.output[1].number: output 2 is configured twice"},
    {"gpio_output_debounce", TCP "[[gpio.output]]\nnumber = 2\nname = \"A\"\ndebounce_ms = 5\n",
     "kerf.toml:6: gpio.output[0].debounce_ms: not for an output"},
    {"gpio_input_on_estop_line",
     TCP "[gpio]\nchip = \"gpiochip0\"\n[gpio.estop]\noffset = 22\n[[gpio.input]]\nnumber = 0\noffset = 22\n",
     "kerf.toml:9: gpio.input[0].offset: line 22 of gpiochip0 is already gpio.estop"},
    {"gpio_output_is_the_torch",
     TCP "[outputs]\ntorch = 1\n[[gpio.output]]\nnumber = 1\nname = \"T\"\n",
     "kerf.toml:6: gpio.output[0].number: output 1 is outputs.torch, which gpio.torch drives: remove one"},
    {"analog_ignore_not_a_number", TCP "[analog]\nignore = [0, \"E1\"]\n",
     "kerf.toml:4: analog.ignore: expected analog numbers 0..255, got a string"},
    {"analog_ignore_range", TCP "[analog]\nignore = [256]\n",
     "kerf.toml:4: analog.ignore: expected analog numbers 0..255, got 256"},
    {"analog_unknown_key", TCP "[analog]\nignored = [1]\n", "kerf.toml:4: analog.ignored: unknown key"},

    // [fit]
    {"fit_criterion_unknown", TCP "[fit]\ncriterion = \"spline\"\n",
     "kerf.toml:4: fit.criterion: unknown criterion \"spline\" (expected vertex, band or biarc)"},
    {"fit_tol_zero", TCP "[fit]\ntol = 0\n", "kerf.toml:4: fit.tol: must be > 0, got 0"},
    {"fit_numeric_unknown", TCP "[fit]\nnumeric = \"float\"\n",
     "kerf.toml:4: fit.numeric: unknown type \"float\" (expected double or fixed)"},
    {"fit_tol_inf", TCP "[fit]\ntol = inf\n", "kerf.toml:4: fit.tol: must be a finite number, got inf"},

    // [cut]
    {"cut_unknown_key", TCP "[cut]\nfeed = 2000\n\npeirce_delay = 0.5\n",
     "kerf.toml:6: cut.peirce_delay: unknown key"},
    {"cut_pierce_negative", TCP "[cut]\npierce_delay = -0.1\n",
     "kerf.toml:4: cut.pierce_delay: must be >= 0, got -0.1"},
    {"cut_arc_ok_timeout_zero", TCP "[cut]\narc_ok_timeout = 0\n",
     "kerf.toml:4: cut.arc_ok_timeout: must be > 0, got 0"},
    {"cut_feed_above_max", TCP "[machine]\nmax_feed = 2000\n[cut]\nfeed = 2500\n",
     "kerf.toml:6: cut.feed: must be <= machine.max_feed (2000), got 2500"},
    {"cut_default_feed_above_max", TCP "[machine]\nmax_feed = 2000\n",
     "kerf.toml:4: cut.feed: must be <= machine.max_feed (2000), got 3000 (the default; set cut.feed)"},
    {"cut_feed_date", TCP "[cut]\nfeed = 2024-01-01\n",
     "kerf.toml:4: cut.feed: expected a number, got a date"},

    // [rt] and the top level
    {"rt_priority_range", TCP "[rt]\npriority = 100\n", "kerf.toml:4: rt.priority: must be in 0..99, got 100"},
    {"rt_lock_memory_number", TCP "[rt]\nlock_memory = 1\n",
     "kerf.toml:4: rt.lock_memory: expected a boolean (true or false), got an integer"},
    {"unknown_section", TCP "[mashine]\naccel = 5\n", "kerf.toml:3: mashine: unknown key"},
    {"unknown_top_level_key", "debug = true\n" TCP, "kerf.toml:1: debug: unknown key"},
    {"first_problem_in_the_file_wins", TCP "[rt]\npriority = 100\n[machine]\naccel = 0\n",
     "kerf.toml:4: rt.priority: must be in 0..99, got 100"},

    // The interpreter's sections: tools, materials, user M-codes, outputs, sim.
    {"tool_without_material", TCP "[tools]\n1 = \"mild\"\n",
     "kerf.toml:4: tools.1: no [materials.mild] section"},
    {"tool_key_not_a_number", TCP "[materials.mild]\nfeed = 2000\n[tools]\nT1 = \"mild\"\n",
     "kerf.toml:6: tools.T1: expected a tool number (0..99999) as the key"},
    {"material_negative_pierce", TCP "[materials.mild]\npierce_delay = -1\n",
     "kerf.toml:4: materials.mild.pierce_delay: must be >= 0, got -1"},
    {"mcode_out_of_range", TCP "[mcodes.M99]\naction = \"ignore\"\n",
     "kerf.toml:3: mcodes.M99: expected a user M-code M100..M199 as the key"},
    {"mcode_bad_action", TCP "[mcodes.M101]\naction = \"blink\"\n",
     "kerf.toml:4: mcodes.M101.action: expected on, off, dwell or ignore, got \"blink\""},
    {"mcode_on_without_output", TCP "[mcodes.M101]\naction = \"on\"\n",
     "kerf.toml:3: mcodes.M101.output: missing (the output number)"},
    {"mcode_dwell_with_output", TCP "[mcodes.M101]\naction = \"dwell\"\nseconds = 1\noutput = 2\n",
     "kerf.toml:6: mcodes.M101.output: only with action = \"on\" or \"off\""},
    {"outputs_unknown_key", TCP "[outputs]\ntorch = 0\nplasma = 1\n",
     "kerf.toml:5: outputs.plasma: unknown key"},
    {"sim_operator_delay_negative", TCP "[sim]\noperator_delay = -1\n",
     "kerf.toml:4: sim.operator_delay: must be >= 0, got -1"},
    {"sim_start_one_number", TCP "[sim]\nstart = [1]\n",
     "kerf.toml:4: sim.start: expected two numbers [x, y] (mm)"},

    // Non-ASCII where toml++ 3.3 tests for whitespace: undefined behaviour in
    // toml++ (found by tests/fuzz/fuzz_config), refused before it parses.
    {"non_ascii_after_key", TCP "[fit]\ntol\xd2\x96 = 0.05\n",
     "kerf.toml:4: syntax error: a non-ASCII character outside a string or comment"},
    {"non_ascii_after_line_ending_backslash", TCP "[fit]\ncriterion = \"\"\"a\\\n  \xc3\xa9\"\"\"\n",
     "kerf.toml:5: syntax error: a non-ASCII character outside a string or comment"},
};

class BadConfig : public testing::TestWithParam<BadCase> {};

TEST_P(BadConfig, GivesItsMessage) {
  Config c;
  std::string error;
  EXPECT_FALSE(parse(GetParam().toml, "kerf.toml", c, error));
  EXPECT_EQ(error, GetParam().message);
}

// Non-ASCII inside comments and strings is fine.
TEST(Config, NonAsciiInCommentsAndStringsIsAccepted) {
  Config c;
  std::string error;
  EXPECT_TRUE(parse("# Ma\xc3\x9f: \xc2\xb1 0.025 mm\n[link] # \xc3\xa9\nkind = \"can\"\n"
                    "iface = \"can0\"  # \xe2\x80\x94\nnode_ids = [1, 2]\n",
                    "kerf.toml", c, error))
      << error;
  EXPECT_EQ(c.link.iface, "can0");
}

TEST(Config, TheInterpretersSectionsAreRead) {
  Config c;
  std::string error;
  ASSERT_TRUE(parse(TCP "[machine]\nstate = \"/var/lib/kerf/state\"\n[materials.mild]\nfeed = 2000\npierce_delay = 0.4\n"
                        "[tools]\n1 = \"mild\"\n[mcodes.M101]\naction = \"dwell\"\nseconds = 0.5\n"
                        "[outputs]\ntorch = 0\nmist = 3\n[sim]\noperator_delay = 0.2\nstart = [10, 2.5]\n",
                    "kerf.toml", c, error))
      << error;
  EXPECT_EQ(c.machine.state, "/var/lib/kerf/state");
  ASSERT_EQ(c.program.tool_material.count(1), 1u);
  EXPECT_EQ(c.program.tool_material.at(1).feed_mm_min, 2000.0);
  EXPECT_EQ(c.program.tool_material.at(1).pierce_delay_s, 0.4);
  ASSERT_EQ(c.program.mcodes.count(101), 1u);
  EXPECT_EQ(c.program.mcodes.at(101).action, job::UserMcode::Action::dwell);
  EXPECT_EQ(c.program.mcodes.at(101).seconds, 0.5);
  EXPECT_EQ(c.program.torch_output, 0);
  EXPECT_EQ(c.program.mist_output, 3);
  EXPECT_EQ(c.program.flood_output, -1);
  EXPECT_EQ(c.sim.operator_delay, 0.2);
  EXPECT_EQ(c.sim.start[0], 10.0);
  EXPECT_EQ(c.sim.start[1], 2.5);
  EXPECT_EQ(defaults().sim.operator_delay, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Config, BadConfig, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<BadCase>& p) { return p.param.name; });

}  // namespace
}  // namespace kerf::config
