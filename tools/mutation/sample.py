"""Keep a random sample of N mutants of formula-like operators in a cosmic-ray session."""
import random, re, sqlite3, sys
db, n = sys.argv[1], int(sys.argv[2])
skip_modules = sys.argv[3].split(",") if len(sys.argv) > 3 and sys.argv[3] else []
c = sqlite3.connect(db)
rows = c.execute("select job_id, module_path, operator_name from mutation_specs").fetchall()
keep_ops = re.compile(r"ReplaceBinaryOperator_(Add|Sub|Mul|Div|Pow|FloorDiv|Mod)_(Add|Sub|Mul|Div|Pow)$|"
                      r"ReplaceComparisonOperator_\w+_(Eq|NotEq|Lt|LtE|Gt|GtE)$|NumberReplacer|ReplaceUnaryOperator_USub|"
                      r"ReplaceUnaryOperator_Delete_USub|AddNot|ReplaceTrueWithFalse|ReplaceFalseWithTrue|ReplaceAndWithOr|"
                      r"ReplaceOrWithAnd|ZeroIterationForLoop|ReplaceBreakWithContinue|ReplaceContinueWithBreak")
ok = [r for r in rows if keep_ops.search(r[2]) and not any(r[1].endswith(m) for m in skip_modules)]
random.Random(36).shuffle(ok)
chosen = {r[0] for r in ok[:n]}
drop = [(r[0],) for r in rows if r[0] not in chosen]
c.executemany("delete from mutation_specs where job_id = ?", drop)
c.executemany("delete from work_items where job_id = ?", drop)
c.commit()
print(db, "eligible", len(ok), "of", len(rows), "kept", len(chosen))
