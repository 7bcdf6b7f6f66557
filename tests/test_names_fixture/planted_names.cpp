// Not compiled: tools/check_test_names.py's self-check must report both of these names.
TEST_CASE("planted: a semicolon; splits the ctest filter", "[planted]") {}
TEST_CASE("planted: an escape \\n reaches the filter as another string", "[planted]") {}
