#include <catch2/catch.hpp>

#include <limits>

#include "core/common/format.h"

using namespace autoblock;

TEST_CASE("format_number prints round numbers as a CAD user writes them", "[common][format]") {
  CHECK(format_number(80) == "80");
  CHECK(format_number(83) == "83");
  CHECK(format_number(-3) == "-3");
  CHECK(format_number(0) == "0");
  CHECK(format_number(-0.0) == "0");
  CHECK(format_number(100000) == "100000");
  CHECK(format_number(0.1) == "0.1");
  CHECK(format_number(2.5) == "2.5");
  CHECK(format_number(-0.125) == "-0.125");
  CHECK(format_number(1234567.25) == "1234567.25");
  CHECK(format_number(0.0005) == "0.0005");
  // Exact without a tolerance: what is printed reads back to the same number.
  CHECK(format_number(1.0 / 3.0) == "0.3333333333333333");
  CHECK(std::stod(format_number(0.1 + 0.2)) == 0.1 + 0.2);
}

TEST_CASE("format_number rounds to a tolerance: noise below it reads 0", "[common][format]") {
  const double tol = 83 * 1e-7;  // the tolerance of a face 83 units across
  CHECK(format_number(-2.22044604925031e-15, tol) == "0");
  CHECK(format_number(2.22044604925031e-15, tol) == "0");
  CHECK(format_number(80.00000000000001, tol) == "80");
  CHECK(format_number(82.99999999999999, tol) == "83");
  CHECK(format_number(3.0000001, tol) == "3");
  CHECK(format_number(12.345678, tol) == "12.345678");
  CHECK(format_number(-0.5, tol) == "-0.5");
  CHECK(format_point(80.00000000000001, -4e-16, tol) == "(80, 0)");
  // A coarse tolerance rounds before the point too.
  CHECK(format_number(123456789012.0, 1e4) == "123456790000");
  CHECK(format_number(0.4, 1.0) == "0");
  CHECK(format_number(1.6, 1.0) == "2");
}

TEST_CASE("format_number uses scientific notation only for huge and tiny values", "[common][format]") {
  CHECK(format_number(1e20) == "1e20");
  CHECK(format_number(-1.5e20) == "-1.5e20");
  CHECK(format_number(1e15) == "1e15");
  CHECK(format_number(999999999999999.0) == "999999999999999");
  CHECK(format_number(2.5e-9) == "2.5e-9");
  CHECK(format_number(1e-7) == "1e-7");
  CHECK(format_number(-3e-300) == "-3e-300");
  // With a tolerance: as many digits as the tolerance allows.
  CHECK(format_number(8.300000000000001e-06, 8.3e-9) == "8.3e-6");
  CHECK(format_number(1.23456789e20, 1e13) == "1.2345679e20");
  CHECK(format_number(std::numeric_limits<double>::infinity()) == "inf");
  CHECK(format_number(std::numeric_limits<double>::quiet_NaN()) == "nan");
}

TEST_CASE("format_significant keeps that many digits, in plain decimals", "[common][format]") {
  CHECK(format_significant(0.61234, 3) == "0.612");
  CHECK(format_significant(12345.6, 4) == "12350");
  CHECK(format_significant(80, 4) == "80");
  CHECK(format_significant(2.0 / 3.0, 4) == "0.6667");
  CHECK(format_significant(3.14159e-7, 3) == "3.14e-7");
  CHECK(format_significant(0, 4) == "0");
}

TEST_CASE("counted and with_article say 1 cut, 2 cuts, an edge", "[common][format]") {
  CHECK(counted(0, "cut") == "0 cuts");
  CHECK(counted(1, "cut") == "1 cut");
  CHECK(counted(2, "cut") == "2 cuts");
  CHECK(counted(1, "vertex", "vertices") == "1 vertex");
  CHECK(counted(7, "vertex", "vertices") == "7 vertices");
  CHECK(with_article("edge") == "an edge");
  CHECK(with_article("solid") == "a solid");
  CHECK(with_article("inner wire") == "an inner wire");
  CHECK(with_article("compound") == "a compound");
}
