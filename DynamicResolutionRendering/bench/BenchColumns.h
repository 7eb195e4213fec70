// The bench row's columns: one table of (name, JSON place, getter, setter)
// drives results.csv's header and rows, results.json's rows and the reload
// of a finished run (--report-from).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/BenchReport.h"

namespace drr {

enum class ColumnKind { Text, Number, Count, Flag };

struct BenchColumn {
  const char* name;  // CSV header
  const char* json;  // JSON pointer inside a row object ("/gpu_ms/frame/median")
  ColumnKind kind;
  int decimals;      // Number: decimals written (CSV and JSON)
  double (*get)(const BenchRow&);     // Number, Count, Flag (1/0)
  void (*set)(BenchRow&, double);
  std::string BenchRow::*text;        // Text
};

const std::vector<BenchColumn>& BenchColumns();

// A number as the files write it: "" for NaN, "inf"/"-inf", else `decimals` decimals.
std::string FormatNumber(double v, int decimals);
// The inverse: "" -> NaN, "inf"/"-inf", else the number (NaN when not one).
double ParseNumber(const std::string& s);

// The fields of one CSV line; a field may be double-quoted (no quotes inside).
std::vector<std::string> SplitCsvLine(const std::string& line);

std::string CsvHeader();
std::string CsvLine(const BenchRow& row);
// One row object; "identical" (valid and MSE 0) and the per-frame values are
// written beside the columns.
nlohmann::json RowJson(const BenchRow& row);
// A row from CSV fields and the column index of each header name; columns
// missing from an older file stay NaN / empty.
BenchRow RowFromFields(const std::vector<std::string>& fields, const std::map<std::string, size_t>& col);

}  // namespace drr

namespace drr {

// results.json: the run's header (adapter, plan, options ...) and its rows.
nlohmann::json BenchJson(const BenchResults& res, const std::string& date);
// The header fields of results.json back into `res` (rows are not read).
bool ReadBenchJsonHeader(const nlohmann::json& j, BenchResults* res, std::string* error);
// The per-frame values of results.json's rows into the rows read from
// results.csv (same order and count).
bool ReadBenchJsonFrames(const nlohmann::json& j, BenchResults* res, std::string* error);

}  // namespace drr
