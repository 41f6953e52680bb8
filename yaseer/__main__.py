from yaseer.entry import main

raise SystemExit(main())
