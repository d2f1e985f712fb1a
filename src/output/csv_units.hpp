// rupture/output/csv_units.hpp
// The unit and meaning of every column of every CSV file a run writes, in one table, written as
// DIR/units.csv (file,column,unit,meaning). The CSV files keep their plain one-line headers (the
// column names are a public interface, and every reader takes them as they are); units.csv
// says what they hold. A test checks that every column a run writes is listed here.
#pragma once
#include <string>
#include <vector>

namespace rupture {

struct CsvColumn {
  const char* file;     // a glob pattern: crack_tip*.csv is crack_tip.csv and crack_tip_NAME.csv
  const char* column;
  const char* unit;     // SI; "-" for a pure number, "" for a count or a flag
  const char* meaning;
};

const std::vector<CsvColumn>& csv_columns();
// DIR/units.csv (rewritten atomically).
void write_csv_units(const std::string& dir);

}  // namespace rupture
