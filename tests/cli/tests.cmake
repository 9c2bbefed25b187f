# SPDX-License-Identifier: MIT
# CTest cases that run the rise-gen binary end to end.
add_test(NAME cli.version COMMAND rise-gen --version)
set_tests_properties(cli.version PROPERTIES PASS_REGULAR_EXPRESSION "^[0-9]+\\.[0-9]+\\.[0-9]+")
