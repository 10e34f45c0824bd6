"""The one layer between the HTTP names and the library's: requests become library arguments (:mod:`.inputs`),
library field names become request paths (:mod:`.fields`: a :class:`FieldContext` per request, the alias
tables of the requests that name their inputs differently) and the library's refusals become error bodies
(:mod:`.refusals`). Nothing else in the service maps a name."""
