# Command-line tests: chain-rom on good and bad scenes (exit codes, one-line messages, no output
# file left behind). Tables come from the closed forms, written into the build tree first.
set(_scenes ${CMAKE_CURRENT_BINARY_DIR}/cli)
add_test(NAME rom_cli_setup
  COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:rom-closed-form-table> -DSRC=${PROJECT_SOURCE_DIR}/data/scenes
          -DDST=${_scenes} -P ${CMAKE_CURRENT_SOURCE_DIR}/cli_setup.cmake)
set_tests_properties(rom_cli_setup PROPERTIES FIXTURES_SETUP rom_cli)

function(rom_cli name)
  cmake_parse_arguments(T "" "EXPECT_EXIT;MATCH;MATCH_STDERR;NO_FILE;PYTHON;LINES;LINES_FILE" "ARGS" ${ARGN})
  add_test(NAME rom_cli_${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:chain-rom> "-DARGS=${T_ARGS}" -DEXPECT_EXIT=${T_EXPECT_EXIT}
            "-DMATCH=${T_MATCH}" "-DMATCH_STDERR=${T_MATCH_STDERR}" "-DNO_FILE=${T_NO_FILE}" "-DPYTHON=${T_PYTHON}" "-DLINES=${T_LINES}"
            "-DLINES_FILE=${T_LINES_FILE}" -DWD=${_scenes} -P ${CMAKE_CURRENT_SOURCE_DIR}/cli_check.cmake)
  set_tests_properties(rom_cli_${name} PROPERTIES FIXTURES_REQUIRED rom_cli)
endfunction()

rom_cli(help ARGS --help EXPECT_EXIT 0 MATCH "spectrum")
rom_cli(spectrum_json ARGS spectrum;top_spheroid.toml;--json EXPECT_EXIT 0
        MATCH "^\\{\"roots\":\\[\\[.*\\]\\],\"stable\":(true|false),\"margin\":[^,]+,\"det_residual\":[^,]+(,.*)?\\}")
rom_cli(spectrum_text ARGS spectrum;three_pendulums.toml EXPECT_EXIT 0 MATCH "stable: yes")
# The text leads with the bodies' roots and sums up the fluid's; --all lists every root.
rom_cli(spectrum_summary ARGS spectrum;top_spheroid.toml EXPECT_EXIT 0 MATCH "and [0-9]+ fluid roots not listed[^\n]*: all real")
rom_cli(spectrum_all ARGS spectrum;top_spheroid.toml;--all EXPECT_EXIT 0 MATCH "fluid 1\\.1")
rom_cli(greenhill_unstable ARGS spectrum;greenhill_prolate.toml;--json EXPECT_EXIT 0 MATCH "\"stable\":false")
rom_cli(run_h5 ARGS run;two_tops.toml;-o;out_two_tops.h5 EXPECT_EXIT 0 MATCH "largest relative drift")
rom_cli(run_csv ARGS run;top_spheroid.toml;-o;out_top.csv EXPECT_EXIT 0 MATCH "wrote out_top.csv")
rom_cli(bad_negative_mass ARGS spectrum;bad_negative_mass.toml EXPECT_EXIT 1 MATCH "^chain-rom: error: [^\n]*body\\[1\\]\\.mass: must be >= 0[^\n]*\n?$")
rom_cli(bad_unknown_key ARGS spectrum;bad_unknown_key.toml EXPECT_EXIT 1 MATCH "body\\[1\\]\\.colour: unknown key")
rom_cli(empty_value ARGS sweep;top_spheroid.toml;--param;body[1].spin;--from=;--to;300;--steps;3;-o;empty.csv EXPECT_EXIT 2
        MATCH "an empty value for --from: give a value" NO_FILE empty.csv)
rom_cli(bad_table ARGS spectrum;bad_not_a_table.toml EXPECT_EXIT 1 MATCH "body\\[1\\]\\.cavity\\.table: .*not an HDF5 file")
rom_cli(bad_modes ARGS spectrum;bad_modes.toml EXPECT_EXIT 1 MATCH "body\\[1\\]\\.cavity\\.modes: 3 requested")
rom_cli(bad_joints ARGS spectrum;bad_joints.toml EXPECT_EXIT 1 MATCH "joint: the chain has 2 bodies and needs 1")
rom_cli(bad_huge_mass_run ARGS run;bad_huge_mass.toml;-o;out_huge.h5 EXPECT_EXIT 1 MATCH "^chain-rom: error: the trajectory is not finite[^\n]*nothing written\n?$" NO_FILE out_huge.h5)
rom_cli(run_unstable_warns ARGS run;unstable_run.toml;-o;out_unstable.h5 EXPECT_EXIT 0 MATCH "wrote out_unstable.h5" MATCH_STDERR "^chain-rom: warning: the scene is unstable .margin, largest .Im sigma. [0-9.]+ rad.s.: the linearised tilts grow")
rom_cli(bad_tilt ARGS run;bad_tilt.toml;-o;out_bad_tilt.h5 EXPECT_EXIT 1 MATCH "initial\\.tilt: has 1 entries" NO_FILE out_bad_tilt.h5)
# run.method against the integrators' registry (linear/integrator.hpp), by every command, before any work.
rom_cli(bad_method_run ARGS run;bad_method.toml;-o;out_bad_method.h5 EXPECT_EXIT 1
        MATCH "bad_method\\.toml: run\\.method: must be one of \"exact\", \"gauss\", \"rk45\" \\(got \"rk4\"\\)"
        NO_FILE out_bad_method.h5)
rom_cli(bad_method_spectrum ARGS spectrum;bad_method.toml EXPECT_EXIT 1 MATCH "run\\.method: must be one of")
rom_cli(bad_prune ARGS spectrum;bad_prune.toml EXPECT_EXIT 1 MATCH "body\\[1\\]\\.cavity\\.prune: must be true or false")
rom_cli(bad_axial_rate ARGS spectrum;bad_axial_rate.toml EXPECT_EXIT 1
        MATCH "initial\\.axial_rate: must be an array of 2 numbers, one per body")
rom_cli(bad_output_dir ARGS run;two_tops.toml;-o;no_such_dir/out.h5 EXPECT_EXIT 1 MATCH "output folder does not exist" NO_FILE no_such_dir/out.h5)
rom_cli(missing_scene ARGS spectrum;nope.toml EXPECT_EXIT 1 MATCH "nope.toml: cannot open")

# Stability maps (chain-rom sweep): a 2D sweep writes K x K2 rows (+ header); bad keys, indices and
# step counts give one line naming the cause, exit 1 and no file.
set(_sw sweep;top_spheroid.toml)
rom_cli(sweep_1d ARGS ${_sw};--param;body[1].spin;--from;50;--to;300;--steps;6;-o;out_sweep1.csv EXPECT_EXIT 0
        MATCH "wrote out_sweep1.csv: 6 points" LINES 7 LINES_FILE out_sweep1.csv)
rom_cli(sweep_2d ARGS ${_sw};--param;body[1].spin;--from;50;--to;300;--steps;4;--param2;body[1].cavity.density;--from2;500;--to2;1500;--steps2;3;-o;out_sweep2.csv
        EXPECT_EXIT 0 MATCH "wrote out_sweep2.csv: 12 points" LINES 13 LINES_FILE out_sweep2.csv)
# The 2-D map tracks its points' roots from their neighbours' (one eigen-solve to start); --no-track solves each.
rom_cli(sweep_2d_tracked ARGS ${_sw};--param;body[1].spin;--from;50;--to;300;--steps;4;--param2;body[1].cavity.density;--from2;500;--to2;1500;--steps2;3;-o;out_sweep3.csv
        EXPECT_EXIT 0 MATCH "roots: 11 points tracked from their neighbours, 1 by the eigen-solver" LINES 13 LINES_FILE out_sweep3.csv)
rom_cli(sweep_2d_no_track ARGS ${_sw};--param;body[1].spin;--from;50;--to;300;--steps;4;--param2;body[1].cavity.density;--from2;500;--to2;1500;--steps2;3;--no-track;-o;out_sweep4.csv
        EXPECT_EXIT 0 MATCH "roots: 0 points tracked from their neighbours, 12 by the eigen-solver" LINES 13 LINES_FILE out_sweep4.csv)
rom_cli(sweep_bad_key ARGS ${_sw};--param;body[1].colour;--from;0;--to;1;--steps;3;-o;out_bad_sweep.csv EXPECT_EXIT 1
        MATCH "^chain-rom: error: --param body\\[1\\]\\.colour: unknown key" NO_FILE out_bad_sweep.csv)
rom_cli(sweep_non_numeric ARGS ${_sw};--param;body[1].cavity.modes;--from;0;--to;1;--steps;3;-o;out_bad_sweep.csv EXPECT_EXIT 1
        MATCH "--param body\\[1\\]\\.cavity\\.modes: not a sweepable number" NO_FILE out_bad_sweep.csv)
# A family of tables (Greenhill: spheroid c/a = 0.5 and 3.5 stable, 2 unstable); a missing member or a
# table key without its pattern stop before any work.
rom_cli(sweep_family ARGS sweep;greenhill_prolate.toml;--param;body[1].cavity.table=family_c%.1f.h5;--from;0.5;--to;3.5;--steps;3;-o;out_family.csv
        EXPECT_EXIT 0 MATCH "wrote out_family.csv: 3 points \\(2 stable, 1 unstable, 0 failed\\)" LINES 4 LINES_FILE out_family.csv)
rom_cli(sweep_family_missing ARGS sweep;greenhill_prolate.toml;--param;body[1].cavity.table=family_c%.1f.h5;--from;0.5;--to;3.5;--steps;4;-o;out_bad_sweep.csv
        EXPECT_EXIT 1 MATCH "table of value 1\\.5: .*family_c1\\.5\\.h5" NO_FILE out_bad_sweep.csv)
rom_cli(sweep_table_no_pattern ARGS ${_sw};--param;body[1].cavity.table;--from;0;--to;1;--steps;3;-o;out_bad_sweep.csv EXPECT_EXIT 1
        MATCH "--param body\\[1\\]\\.cavity\\.table: a family of tables is swept as" NO_FILE out_bad_sweep.csv)
rom_cli(sweep_bad_index ARGS ${_sw};--param;body[2].spin;--from;0;--to;1;--steps;3;-o;out_bad_sweep.csv EXPECT_EXIT 1
        MATCH "--param body\\[2\\]\\.spin: body index 2 out of range 1\\.\\.1" NO_FILE out_bad_sweep.csv)
rom_cli(sweep_bad_index2 ARGS ${_sw};--param;body[1].spin;--from;0;--to;1;--steps;3;--param2;joint[1].stiffness;--from2;0;--to2;1;--steps2;2;-o;out_bad_sweep.csv
        EXPECT_EXIT 1 MATCH "--param2 joint\\[1\\]\\.stiffness: the scene has no joints" NO_FILE out_bad_sweep.csv)
rom_cli(sweep_bad_steps ARGS ${_sw};--param;body[1].spin;--from;0;--to;1;--steps;0;-o;out_bad_sweep.csv EXPECT_EXIT 1
        MATCH "--steps 0: must be >= 1" NO_FILE out_bad_sweep.csv)
rom_cli(sweep_bad_steps2 ARGS ${_sw};--param;body[1].spin;--from;0;--to;1;--steps;2;--param2;system.gravity;--from2;0;--to2;1;--steps2;-3;-o;out_bad_sweep.csv
        EXPECT_EXIT 1 MATCH "--steps2 -3: must be >= 1" NO_FILE out_bad_sweep.csv)
rom_cli(sweep_bad_value ARGS ${_sw};--param;body[1].mass;--from;-1;--to;1;--steps;3;-o;out_bad_sweep.csv EXPECT_EXIT 1
        MATCH "--from \\(--param\\) body\\[1\\]\\.mass: value -1 out of range: must be >= 0" NO_FILE out_bad_sweep.csv)
rom_cli(sweep_no_python ARGS ${_sw};--param;body[1].spin;--from;50;--to;300;--steps;3;-o;out_bad_sweep.csv;--png;out_bad_sweep.png
        PYTHON /nonexistent/python3 EXPECT_EXIT 1 MATCH "--png: /nonexistent/python3 with matplotlib" NO_FILE out_bad_sweep.csv)
execute_process(COMMAND /usr/bin/python3 -c "import matplotlib, numpy" RESULT_VARIABLE _no_mpl OUTPUT_QUIET ERROR_QUIET)
if(_no_mpl EQUAL 0)
  rom_cli(sweep_png ARGS ${_sw};--param;body[1].spin;--from;50;--to;300;--steps;4;--param2;system.gravity;--from2;0;--to2;20;--steps2;3;-o;out_sweep3.csv;--png;out_sweep3.png
          EXPECT_EXIT 0 MATCH "wrote out_sweep3.png")
else()
  message(STATUS "rom_cli_sweep_png not registered: /usr/bin/python3 lacks matplotlib or numpy")
endif()

# Error against run time (chain-rom bench): it prints every kind of row and writes the CSV (its format is
# checked by Bench.CsvIsWellFormed); bad input (no [run], --png without -o, a missing folder) stops with
# one line, exit 1, no file.
rom_cli(bench_csv ARGS bench;top_spheroid.toml;-o;out_bench.csv EXPECT_EXIT 0
        MATCH "exact \\(double\\) +error .*gauss h = .*rk45 tol = .*wrote out_bench.csv: [0-9]+ rows")
rom_cli(bench_no_run ARGS bench;greenhill_prolate.toml;-o;out_bad_bench.csv EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*greenhill_prolate.toml: run: missing \\[run\\] section" NO_FILE out_bad_bench.csv)
rom_cli(bench_png_needs_csv ARGS bench;top_spheroid.toml;--png;out_bad_bench.png EXPECT_EXIT 1
        MATCH "--png: needs -o" NO_FILE out_bad_bench.png)
rom_cli(bench_bad_output_dir ARGS bench;top_spheroid.toml;-o;no_such_dir/b.csv EXPECT_EXIT 1
        MATCH "output folder does not exist" NO_FILE no_such_dir/b.csv)
rom_cli(bench_missing_scene ARGS bench;nope.toml;-o;out_bad_bench.csv EXPECT_EXIT 1 MATCH "nope.toml: cannot open"
        NO_FILE out_bad_bench.csv)
if(_no_mpl EQUAL 0)
  rom_cli(bench_png ARGS bench;two_tops.toml;-o;out_bench2.csv;--png;out_bench2.png EXPECT_EXIT 0 MATCH "wrote out_bench2.png")
endif()

# The nonlinear model (docs/rom.md, "Nonlinear chain"): a run at 17 degrees writes attitudes and spins; what only
# it takes (B != A, moments) goes to the chain without axial symmetry in the linear commands, whose linear run refuses
# the moment; a tank rides along; a bad moment is refused.
rom_cli(run_nonlinear ARGS run;nonlinear_chain.toml;-o;out_nonlinear.h5 EXPECT_EXIT 0
        MATCH "wrote out_nonlinear.h5: 5001 samples, model nonlinear[^\n]*\nenergy: [^\n]*angular momentum")
rom_cli(nonlinear_scene_linear_spectrum ARGS spectrum;nonlinear_chain.toml EXPECT_EXIT 0
        MATCH "^fixed chain without axial symmetry, 3 bodies")
rom_cli(asymmetric_moment_linear_run ARGS run;bad_asymmetric_moment_linear_run.toml;-o;out_asym_moment.h5 EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*body\\[1\\]\\.moment: an external moment drives the chain[^\n]*model = \"nonlinear\"[^\n]*\n?$"
        NO_FILE out_asym_moment.h5)
# The chain without axial symmetry (docs/rom.md, "Bodies and tanks without axial symmetry"): bench, run and sweep.
rom_cli(asymmetric_top_bench ARGS bench;asymmetric_top.toml;-o;out_asym_bench.csv EXPECT_EXIT 0
        MATCH "exact \\(double\\)[^\n]*\n[^\n]*gauss[^$]*wrote out_asym_bench.csv")
rom_cli(asymmetric_top_run ARGS run;asymmetric_top.toml;-o;out_asym_run.h5 EXPECT_EXIT 0
        MATCH "wrote out_asym_run.h5: 11 samples, the chain without axial symmetry propagated exactly[^\n]*\nvalidity: the nonlinear chain differs by")
rom_cli(asymmetric_top_sweep ARGS sweep;asymmetric_top.toml;--param;body[1].spin;--from;20;--to;200;--steps;4;-o;out_asym_sweep.csv
        EXPECT_EXIT 0 MATCH "wrote out_asym_sweep.csv: 4 points")
rom_cli(run_nonlinear_tank ARGS run;nonlinear_tank.toml;-o;out_nl_tank.h5 EXPECT_EXIT 0
        MATCH "wrote out_nl_tank.h5: 101 samples, model nonlinear[^\n]*\nenergy: not an integral with fluid tanks")
rom_cli(bad_moment ARGS run;bad_moment.toml;-o;out_bad_moment.h5 EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*body\\[1\\]\\.moment\\.frequency: missing: a harmonic moment needs it" NO_FILE out_bad_moment.h5)
rom_cli(bad_force ARGS run;bad_force.toml;-o;out_bad_force.h5 EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*body\\[1\\]\\.force\\.at: " NO_FILE out_bad_force.h5)
rom_cli(bad_field ARGS run;bad_field.toml;-o;out_bad_field.h5 EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*field\\.harmonic: a time-varying axial field changes the chain's stiffness" NO_FILE out_bad_field.h5)
rom_cli(bad_gradient ARGS run;bad_gradient.toml;-o;out_bad_gradient.h5 EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*field\\.gradient: is not symmetric: only a potential field's gradient" NO_FILE out_bad_gradient.h5)
rom_cli(bad_gradient_axis ARGS spectrum;bad_gradient_axis.toml EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*field\\.gradient: has xx != yy: the linearised chain \\(26\\) needs a gradient symmetric")
rom_cli(bad_nonlinear_tilt ARGS run;bad_nonlinear_tilt.toml;-o;out_bad_nl_tilt.h5 EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*initial\\.tilt\\[1\\]: Krylov angles beta = Re u = 2, [^\n]*outside" NO_FILE out_bad_nl_tilt.h5)
# The linear run measures its own validity against the nonlinear chain (with its tanks) and warns past 1 %.
rom_cli(run_validity ARGS run;two_tops.toml;-o;out_validity.h5 EXPECT_EXIT 0
        MATCH "validity: the nonlinear chain differs by")
rom_cli(run_validity_warns ARGS run;large_tilt_run.toml;-o;out_large_tilt.h5 EXPECT_EXIT 0 MATCH "wrote out_large_tilt.h5"
        MATCH_STDERR "^chain-rom: warning: at this amplitude \\(0\\.3 rad\\) the tilts differ from the nonlinear chain's by [0-9.]+ %")

# Frequency response (chain-rom response): a CSV of N rows after its resonance comments and header, the Bode plot,
# and bad ranges or bodies refused in one line with no file.
set(_rs response;top_spheroid.toml)
rom_cli(response_csv ARGS ${_rs};--body;1;--freq;-400:400:41;-o;out_response.csv EXPECT_EXIT 0
        MATCH "resonances in the range[^\n]*\nwrote out_response.csv")
rom_cli(response_bad_range ARGS ${_rs};--body;1;--freq;5:1:10;-o;out_bad_response.csv EXPECT_EXIT 1
        MATCH "^chain-rom: error: --freq 5:1:10: need finite FROM < TO\n?$" NO_FILE out_bad_response.csv)
rom_cli(response_bad_count ARGS ${_rs};--body;1;--freq;0:1:1;-o;out_bad_response.csv EXPECT_EXIT 1
        MATCH "--freq 0:1:1: N must be in 2\\.\\.1000000" NO_FILE out_bad_response.csv)
rom_cli(response_bad_text ARGS ${_rs};--body;1;--freq;0:x:3;-o;out_bad_response.csv EXPECT_EXIT 1
        MATCH "--freq 0:x:3: expected FROM:TO:N with numbers" NO_FILE out_bad_response.csv)
rom_cli(response_bad_body ARGS ${_rs};--body;2;--freq;0:1:3;-o;out_bad_response.csv EXPECT_EXIT 1
        MATCH "--body 2: the scene has bodies 1\\.\\.1" NO_FILE out_bad_response.csv)
if(_no_mpl EQUAL 0)
  rom_cli(response_png ARGS ${_rs};--body;1;--freq;-400:400:41;-o;out_response2.csv;--png;out_response2.png
          EXPECT_EXIT 0 MATCH "wrote out_response2.png")
endif()

# A massless shell's spin: its ideal liquid does not follow it (docs/physics.md §3, "Axial rotations"), so an axial
# friction on it, or the nonlinear chain, is refused in one line.
rom_cli(bad_massless_axial ARGS spectrum;bad_massless_axial.toml EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*body\\[1\\]\\.C: the shell has no axial inertia[^\n]*give the shell's C > 0")
rom_cli(bad_massless_nonlinear ARGS run;bad_massless_nonlinear.toml;-o;out_bad_massless.h5 EXPECT_EXIT 1
        MATCH "^chain-rom: error: [^\n]*body\\[1\\]\\.C: the shell has no axial inertia[^\n]*give the shell's C > 0"
        NO_FILE out_bad_massless.h5)
