### integrators

integrators-join = { " ; " }
integrators-legend-dp45-order = DP45 : { $order }
integrators-overflow-note = dépassement de capacité à t = { $time }
integrators-failed = échec
integrators-stable-yes = oui
integrators-stable-no = non
integrators-method-euler = Euler explicite
integrators-method-symplectic-euler = Euler symplectique
integrators-method-heun = Heun
integrators-method-rk4 = RK4
integrators-legend-symplectic-euler = Euler sympl. ×
integrators-legend-dp45 = DP45 ● pas
integrators-legend-growing = { $legend } ×{ $growth }/pas ↑
integrators-legend-order = { $legend } : { $order }
integrators-legend-no-fit = { $legend } : pas d'ajustement
integrators-legend-dp45-no-order = DP45 : pas d'ordre
integrators-series-exact = exacte
integrators-axis-error = erreur |x_num − x_exact|
integrators-axis-step = pas h
integrators-axis-max-error = erreur maximale
integrators-axis-re = partie réelle Re(hλ)
integrators-axis-im = partie imaginaire Im(hλ)
integrators-axis-evaluations = évaluations du second membre N
integrators-limit-up-to = stable pour h ≤ { $step }
integrators-limit-every = stable pour tout h
integrators-limit-none = instable pour tout h
integrators-method-overflows = { $method } : dépassement de capacité à t = { $time } (×{ $growth } par pas)
integrators-method-diverges = { $method } diverge (×{ $growth } par pas), erreur maximale { $error }
integrators-method-diverges-clipped = { $method } diverge (×{ $growth } par pas, écrêté), erreur maximale { $error }
integrators-method-bounded = { $method } reste borné (×{ $growth } par pas), erreur maximale { $error }
integrators-dp45-words = DP45 a fait { $steps ->
        [one] { $steps } pas
       *[other] { $steps } pas
    } (tolérance { $tolerance }), erreur maximale { $error }
integrators-dp45-failed = échec de DP45 : { $reason }
integrators-failed-underflow = le pas est devenu trop petit pour avancer à t = { $time } (le problème est peut-être trop raide ou singulier)
integrators-failed-max-steps = abandon à t = { $time } après { $steps } pas
integrators-failed-non-finite = la solution est devenue infinie ou indéfinie à t = { $time } (essayez un pas plus petit)
integrators-describe-response = Chaque méthode face à l'oscillation amortie exacte sur { $duration } avec h = { $step } ({ $steps } pas). { $methods }. Le graphique montre ±{ $range } fois l'amplitude exacte ; les courbes qui la dépassent sont écrêtées au bord.
integrators-describe-response-last = Chaque méthode face à l'oscillation amortie exacte sur { $duration } avec h = { $step } ({ $steps } pas, le dernier de { $last } pour finir à T). { $methods }. Le graphique montre ±{ $range } fois l'amplitude exacte ; les courbes qui la dépassent sont écrêtées au bord.
integrators-error-peak = { $method } : maximum { $error } à t = { $time }
integrators-error-peak-growing = { $method } : maximum { $error } à t = { $time }, croissante
integrators-error-none = { $method } : aucune erreur finie
integrators-error-no-method = Aucune méthode n'est activée.
integrators-describe-error = Erreur |x_num − x_exact| en échelle logarithmique aux points de grille de chaque méthode (h = { $step }) : { $methods }.
integrators-describe-error-clipped = Erreur |x_num − x_exact| en échelle logarithmique aux points de grille de chaque méthode (h = { $step }) : { $methods }. Les erreurs supérieures à { $clip } sont écrêtées en haut.
integrators-fit = { $method } : pente ajustée { $slope } (h = { $from } … { $to })
integrators-fit-overflows = { $method } : pente ajustée { $slope } (h = { $from } … { $to }), dépassement de capacité pour h ≥ { $limit }
integrators-no-fit = { $method } : pas d'ajustement (trop peu de points dans le domaine asymptotique)
integrators-no-fit-overflows = { $method } : pas d'ajustement (trop peu de points dans le domaine asymptotique), dépassement de capacité pour h ≥ { $limit }
integrators-slope = pente { $order }
integrators-describe-convergence = Erreur maximale en { $points } points de contrôle communs en fonction du pas h, pour au plus { $levels } pas divisés par deux à partir de { $from } (au plus { $budget } pas par méthode au total, { $euler_budget } pour Euler explicite ; les pas plus fins sont omis). { $methods }. Chaque ordre est ajusté sur le seul domaine asymptotique, tracé en segment épais : les pas les plus fins dont les pentes locales concordent à { $spread } près, avec des erreurs inférieures à { $ceiling } et supérieures à 1e-10 de x₀. Les pentes de référence 1 et 4 sont en pointillés ; le h actuel est la verticale en tirets. DP45 n'a pas de h unique : voir le graphique travail–précision.
integrators-off-scale = { $name } = { $value } (hors échelle)
integrators-path = hλ quand h augmente
integrators-z-real-pair = z = hλ = { $z1 } et { $z2 }
integrators-region-inside = { $method } : dans sa région, |R| = { $growth }, { $limit }
integrators-region-outside = { $method } : hors de sa région, |R| = { $growth }, { $limit }
integrators-describe-stability = Régions de stabilité |R(z)| ≤ 1 dans le plan complexe de z = hλ (l'intérieur de chaque courbe fermée ; celle d'Euler explicite est le disque |1 + z| ≤ 1). Les deux pôles du système avec h = { $step } donnent { $z }. { $methods }. Euler symplectique n'est pas une application scalaire R(z) : sa matrice de pas 2×2 a ici un rayon spectral de { $radius }, { $limit }. DP45 choisit lui-même ses pas et les garde stables.
integrators-work-words = { $method } : de { $error_first } avec { $work_first } évaluations à { $error_last } avec { $work_last }
integrators-describe-work = Erreur maximale en fonction du travail qu'elle a coûté, compté en évaluations du second membre f, en axes log–log, pour chaque méthode : celles à pas fixe aux pas de l'étude de convergence (erreur en ses points de contrôle communs), DP45 aux tolérances { $from } … { $to } (erreur sur ses pas acceptés). Plus bas est plus précis, plus à gauche est moins coûteux ; une méthode d'ordre p descend avec une pente −p ; les calculs de DP45 sont des points là où la tolérance fixe leurs pas et des croix là où c'est la stabilité. { $methods }.
integrators-dp45-stability-runs = calculs dont la stabilité fixe les pas (plus de { $share } des pas à { $fraction } ou plus de son plus grand pas stable) : { $count }/{ $runs }
integrators-dp45-order = DP45 : ordre observé { $order } (ajusté sur { $from } … { $to } évaluations, là où la tolérance fixe ses pas) ; { $runs }
integrators-dp45-no-order = DP45 n'a pas d'ordre observé : la stabilité fixe ses pas, ou il reste trop peu de calculs dans le domaine asymptotique ; { $runs }
integrators-title = Intégrateurs numériques et leur erreur
integrators-summary = L'oscillateur libre intégré par Euler explicite, Euler symplectique, Heun (RK2) et RK4 classique à pas fixe h, et par Dormand–Prince 5(4) à pas adaptatif, chacun comparé à la solution exacte. Une méthode à un pas multiplie chaque mode par R(hλ) à chaque pas : quand |R| > 1, les nombres croissent quelle que soit la fidélité avec laquelle la méthode approche l'équation, ce qui explique pourquoi Euler explicite fait exploser un oscillateur faiblement amorti sauf si h < 2ζ/ωₙ. Quand elle est stable, diviser h par deux divise l'erreur par 2^p, où p est l'ordre de convergence de la méthode : le graphique de convergence mesure p. Désactiver une méthode masque ses courbes ; ses valeurs affichées restent calculées.
integrators-param-zeta = taux d'amortissement
integrators-param-wn = pulsation propre
integrators-param-h = pas
integrators-param-T = durée
integrators-param-x0 = déplacement initial
integrators-param-tol = tolérance de DP45 (relative ; absolue tol·x₀)
integrators-param-euler = Euler explicite
integrators-param-symplectic-euler = Euler symplectique
integrators-param-heun = Heun (RK2)
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4), adaptatif
integrators-readout-h-used = pas utilisé : exactement h (un dernier pas plus court termine le calcul à T)
integrators-readout-h-last = dernier pas, qui termine le calcul à T
integrators-readout-max-err-euler = erreur maximale, Euler explicite
integrators-readout-max-err-symplectic-euler = erreur maximale, Euler symplectique
integrators-readout-max-err-heun = erreur maximale, Heun
integrators-readout-max-err-rk4 = erreur maximale, RK4
integrators-readout-max-err-dp45 = erreur maximale, DP45
integrators-readout-order-euler = ordre ajusté, Euler explicite
integrators-readout-order-symplectic-euler = ordre ajusté, Euler symplectique
integrators-readout-order-heun = ordre ajusté, Heun
integrators-readout-order-rk4 = ordre ajusté, RK4
integrators-readout-order-dp45 = ordre observé, DP45 (erreur en fonction des évaluations de f, là où la tolérance fixe les pas)
integrators-readout-stable-euler = stable à ce h, Euler explicite
integrators-readout-stable-symplectic-euler = stable à ce h, Euler symplectique
integrators-readout-stable-heun = stable à ce h, Heun
integrators-readout-stable-rk4 = stable à ce h, RK4
integrators-readout-growth-euler = croissance par pas |R(hλ)|, Euler explicite
integrators-readout-growth-symplectic-euler = croissance par pas (rayon spectral), Euler symplectique
integrators-readout-growth-heun = croissance par pas |R(hλ)|, Heun
integrators-readout-growth-rk4 = croissance par pas |R(hλ)|, RK4
integrators-readout-steps-dp45 = pas acceptés par DP45
integrators-plot-response = Solutions numériques et x(t) exacte
integrators-plot-error = Erreur au cours du temps
integrators-plot-convergence = Convergence : erreur maximale en fonction du pas h
integrators-plot-work = Travail–précision : erreur maximale en fonction des évaluations de f
integrators-plot-stability = Régions de stabilité et z = hλ
integrators-preset-1 = Faiblement amorti, h = 0,3 s
integrators-preset-2 = Euler tout juste stable, h = 0,04 s
integrators-preset-3 = RK4 au-delà de sa limite, h = 1,6 s
integrators-preset-4 = Non amorti, h = 0,1 s
integrators-preset-5 = Raide et suramorti ζ = 2, ωₙ = 20
integrators-table-caption = Les méthodes
integrators-table-column-1 = méthode
integrators-table-column-2 = ordre p
integrators-table-column-3 = évaluations de f par pas
integrators-table-column-4 = facteur d'amplification R(z)
integrators-table-column-5 = sur un oscillateur non amorti
integrators-table-euler-1 = Euler explicite
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = croît toujours : |R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = Euler symplectique
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = matrice 2×2, pas un R scalaire
integrators-table-symplectic-euler-5 = erreur d'énergie bornée tant que ωh ≤ 2
integrators-table-heun-1 = Heun (RK2)
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = croît lentement : |R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = RK4 classique
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = amortit légèrement tant que ωh ≤ 2√2
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6 (la dernière sert de première)
integrators-table-dp45-4 = adaptatif : h suit l'estimation d'erreur
integrators-table-dp45-5 = stable : les pas rejetés réduisent h

### nonlinear

nonlinear-effect-linear = linéaire
nonlinear-effect-hardening = ressort raidissant
nonlinear-effect-softening = ressort assouplissant
nonlinear-effect-stick-slip = adhérence-glissement
nonlinear-effect-bump-stop = choc sur la butée
nonlinear-effect-asymmetric = amortisseur asymétrique
nonlinear-effect-several = plusieurs à la fois
nonlinear-effect-escaped = échappement
nonlinear-join = { "\u00A0; " }
nonlinear-differ = elles diffèrent au plus de { $deviation } à t = { $time }
nonlinear-first-swing = première oscillation { $nonlinear } contre { $linear } en linéaire (rapport { $ratio })
nonlinear-sticks-at = le frottement retient la masse à { $position } à partir de { $time }
nonlinear-escapes = le calcul non linéaire sort du graphique (|x| > { $limit }) à { $time }
nonlinear-describe-response = { $effect } : les deux partent ensemble ; { $clauses }.
nonlinear-describe-phase = Plan de phase : les deux trajectoires partent de x = { $x0 }, v = { $v0 }. La linéaire s'enroule en spirale vers ({ $x_linear }, { $v_linear }) ; la non linéaire finit en x = { $x_end }, v = { $v_end }, avec une vitesse maximale de { $speed } contre { $speed_linear } en linéaire.
nonlinear-describe-spring = Force de rappel en fonction de l'extension sur ±{ $reach } : le ressort linéaire est la droite k·x ; au plus grand débattement, { $travel }, la force non linéaire vaut { $force } contre { $linear } en linéaire.
nonlinear-describe-spring-stops = Force de rappel en fonction de l'extension sur ±{ $reach } : le ressort linéaire est la droite k·x ; au plus grand débattement, { $travel }, la force non linéaire vaut { $force } contre { $linear } en linéaire, les butées ajoutant { $rate } au-delà de ±{ $gap }.
nonlinear-describe-damper = Force d'amortisseur et de frottement en fonction de la vitesse sur ±{ $speed } : à +{ $speed } (détente) elle vaut { $rebound }, à −{ $speed } (compression) { $compression } ; l'amortisseur moyen du modèle linéaire donne ±{ $linear }.
nonlinear-describe-damper-friction = Force d'amortisseur et de frottement en fonction de la vitesse sur ±{ $speed } : à +{ $speed } (détente) elle vaut { $rebound }, à −{ $speed } (compression) { $compression } ; l'amortisseur moyen du modèle linéaire donne ±{ $linear } ; le frottement de glissement ajoute un saut de ±{ $friction } en v = 0, et au repos le frottement statique retient jusqu'à ±{ $holding }.
nonlinear-axis-velocity-rebound = vitesse v (+ détente)
nonlinear-series-stops = butées ±{ $gap }
nonlinear-series-linear = modèle linéaire
nonlinear-series-nonlinear = non linéaire (RK4)
nonlinear-marker-sticks = adhère
nonlinear-marker-start = départ
nonlinear-series-linear-spring = k·x linéaire
nonlinear-series-spring = k·x + k₃·x³ + butées
nonlinear-series-linear-damper = c̄·v linéaire
nonlinear-series-damper = amortisseur + frottement
nonlinear-schematic = Quart de véhicule à t = { $time } : suspension détendue de { $extension }.
nonlinear-schematic-pressing = Quart de véhicule à t = { $time } : suspension détendue de { $extension }, en appui sur une butée.
nonlinear-schematic-clear = Quart de véhicule à t = { $time } : suspension détendue de { $extension }, hors contact avec les butées.
nonlinear-title = Au-delà du modèle linéaire
nonlinear-summary = Une suspension réelle n'est linéaire que pour de petits mouvements. Ici, le quart de véhicule reçoit un ressort cubique (k₃ > 0 raidissant, k₃ < 0 assouplissant), un amortisseur plus ferme en détente (x′ > 0) qu'en compression, un frottement de Coulomb dans les articulations et des butées en caoutchouc au-delà de ±gap. Le frottement alterne adhérence et glissement : tant que la masse glisse, il freine avec la force F_c ; une fois qu'elle s'arrête, le frottement statique la retient jusqu'à F_static, un multiple fixé de F_c, et elle ne repart que si le ressort tire plus fort. Le mouvement est intégré par RK4, chaque arrêt localisé à l'intérieur de son pas, et tracé face au modèle linéaire m·x″ + c̄·x′ + k·x = 0 (c̄ le coefficient moyen de l'amortisseur) depuis le même départ. Observez où la prédiction échoue : la période dépend de l'amplitude (un ressort raidissant la raccourcit, un ressort assouplissant l'allonge), le frottement fait décroître l'amplitude en ligne droite puis retient définitivement la masse hors du centre (adhérence-glissement), une butée transforme une oscillation douce en choc, et un amortisseur asymétrique décale la position moyenne. Les valeurs par défaut sont un coin de voiture plausible : 300 kg, 24 kN/m (1,4 Hz), un amortisseur de 1 500 N·s/m (ζ ≈ 0,28) et un ressort légèrement progressif. x est l'extension de la suspension depuis l'équilibre statique (positive = caisse vers le haut).
nonlinear-param-m = masse suspendue
nonlinear-param-k = raideur linéaire du ressort
nonlinear-param-k3 = coefficient cubique du ressort (+ raidissant, − assouplissant)
nonlinear-param-c-comp = coefficient d'amortissement en compression
nonlinear-param-c-reb = coefficient d'amortissement en détente
nonlinear-param-friction = force de frottement de Coulomb en glissement
nonlinear-param-stick-ratio = rapport frottement statique / frottement de glissement
nonlinear-param-gap = jeu avant la butée
nonlinear-param-k-stop = raideur de butée (0 = sans butées)
nonlinear-param-x0 = extension initiale
nonlinear-param-v0 = vitesse initiale
nonlinear-readout-effect = non-linéarité dominante
nonlinear-readout-period-ratio = rapport des périodes de la première oscillation T_nonlinear / T_linear
nonlinear-readout-max-deviation = plus grand |x_nonlinear − x_linear|
nonlinear-readout-period-nonlinear = période non linéaire de la première oscillation complète (trois passages par zéro)
nonlinear-readout-period-linear = période linéaire de la première oscillation complète (= 2π/ω_d)
nonlinear-readout-max-travel = plus grand |x| (non linéaire)
nonlinear-readout-stick-position = le frottement retient la masse à
nonlinear-plot-response = Réponse non linéaire et linéaire x(t)
nonlinear-plot-phase = Plan de phase (x, v)
nonlinear-plot-spring = Force du ressort et des butées
nonlinear-plot-damper = Force de l'amortisseur et du frottement
nonlinear-preset-1 = Linéaire (tout désactivé)
nonlinear-preset-2 = Ressort raidissant
nonlinear-preset-3 = Ressort assouplissant
nonlinear-preset-4 = Frottement adhérence–glissement
nonlinear-preset-5 = Choc sur la butée
nonlinear-preset-6 = Amortisseur asymétrique
nonlinear-table-caption = Où le modèle linéaire échoue
nonlinear-table-column-1 = non-linéarité
nonlinear-table-column-2 = loi de force
nonlinear-table-column-3 = ce que le modèle linéaire manque
nonlinear-table-column-4 = signature sur les graphiques
nonlinear-table-linear-1 = Aucune (linéaire)
nonlinear-table-linear-2 = k·x + c·x′
nonlinear-table-linear-3 = rien : le modèle est exact
nonlinear-table-linear-4 = les deux courbes coïncident
nonlinear-table-hardening-spring-1 = Ressort raidissant
nonlinear-table-hardening-spring-2 = k·x + k₃·x³, k₃ > 0
nonlinear-table-hardening-spring-3 = la fréquence croît avec l'amplitude
nonlinear-table-hardening-spring-4 = période plus courte tant que l'oscillation est grande ; les courbes s'écartent
nonlinear-table-softening-spring-1 = Ressort assouplissant
nonlinear-table-softening-spring-2 = k·x + k₃·x³, k₃ < 0
nonlinear-table-softening-spring-3 = la fréquence décroît avec l'amplitude ; au-delà de √(−k/k₃) le ressort cède
nonlinear-table-softening-spring-4 = période plus longue ; un grand départ peut s'échapper
nonlinear-table-stick-slip-1 = Frottement de Coulomb
nonlinear-table-stick-slip-2 = F_c·sgn(x′) en glissement ; jusqu'à F_static au repos
nonlinear-table-stick-slip-3 = l'amplitude décroît d'environ 4F_c/k par cycle, en ligne droite, puis la masse reste collée définitivement là où |k·x| ≤ F_static
nonlinear-table-stick-slip-4 = enveloppe rectiligne ; une fin plate hors de zéro
nonlinear-table-bump-stop-impact-1 = Butées
nonlinear-table-bump-stop-impact-2 = k_stop·(|x| − gap) au-delà de ±gap
nonlinear-table-bump-stop-impact-3 = un contact brusque et raide : grande force, inversion rapide
nonlinear-table-bump-stop-impact-4 = pics écrêtés à ±gap ; cassures dans la boucle de phase
nonlinear-table-asymmetric-damper-1 = Amortisseur asymétrique
nonlinear-table-asymmetric-damper-2 = c_r·x′ en détente, c_c·x′ en compression
nonlinear-table-asymmetric-damper-3 = un décalage de la position moyenne (effet de « jacking ») et des demi-cycles inégaux
nonlinear-table-asymmetric-damper-4 = décroissance dissymétrique ; la spirale de phase est décentrée
nonlinear-table-several-at-once-1 = Plusieurs à la fois
nonlinear-table-several-at-once-2 = somme des précédentes
nonlinear-table-several-at-once-3 = leurs effets s'ajoutent et interagissent
nonlinear-table-several-at-once-4 = voir chaque ligne
nonlinear-table-escaped-1 = Ressort assouplissant au-delà de sa limite
nonlinear-table-escaped-2 = k·x + k₃·x³ < 0 pour |x| > √(−k/k₃)
nonlinear-table-escaped-3 = le modèle cesse de décrire une suspension
nonlinear-table-escaped-4 = le calcul est interrompu là où |x| dépasse 1 m

### uncertainty

uncertainty-quantity-zeta = taux d'amortissement ζ
uncertainty-quantity-f0 = fréquence propre f0
uncertainty-quantity-q = facteur de qualité Q
uncertainty-quantity-bandwidth = bande passante à demi-puissance
uncertainty-quantity-settling-time = temps d'établissement de la réponse libre (±5 %)
uncertainty-hist-title = Monte-Carlo : { $quantity }
uncertainty-draws-provisional = { $draws } ({ $full } en cours)
uncertainty-band-nominal-mass = m nominale
uncertainty-band-lowest-corner = coin de ζ minimal
uncertainty-band-nominal = nominal
uncertainty-band-highest-corner = coin de ζ maximal
uncertainty-never = jamais
uncertainty-band-suspension = Réponse libre depuis { $start } avec la masse suspendue à +{ $percent } %, nominale et à −{ $percent } %
uncertainty-band-rlc = Tension du condensateur depuis 1 V au coin de ζ minimal, au nominal et au coin de ζ maximal de la boîte de tolérances
uncertainty-ignored-rlc = Les curseurs du RLC sont ignorés.
uncertainty-ignored-suspension = Les curseurs de la suspension sont ignorés.
uncertainty-zeta-undefined = ζ n'est pas défini à une extrémité de l'intervalle
uncertainty-zeta-spans = ζ va de { $low } à { $high }
uncertainty-describe-band = { $what } : { $zeta } ; temps d'établissement à 5 % (croix) : { $first }, { $second } et { $third }. { $ignored }
uncertainty-dist-normal = normaux (tolérance = 3σ)
uncertainty-dist-uniform = uniformes
uncertainty-spec-zeta = La fenêtre de spécification de ζ, { $low }–{ $high }, est marquée ; { $share } des tirages respectent toute la spécification.
uncertainty-spec-settling-time = La limite de spécification, { $limit }, est marquée.
uncertainty-no-finite = Aucun tirage ne donne de valeur finie de la grandeur « { $quantity } ».
uncertainty-describe-histogram = Histogramme de la grandeur « { $quantity } » sur { $draws } tirages { $distribution } : de { $low } à { $high }, 5ᵉ centile { $p5 }, 95ᵉ centile { $p95 }.
uncertainty-describe-histogram-spec = Histogramme de la grandeur « { $quantity } » sur { $draws } tirages { $distribution } : de { $low } à { $high }, 5ᵉ centile { $p5 }, 95ᵉ centile { $p95 }. { $spec }
uncertainty-provisional-title = { $title } (provisoire)
uncertainty-provisional-description = Provisoire : d'après les { $shown } premiers tirages, tandis que le calcul de { $full } se poursuit. { $description }
uncertainty-axis-capacitor-voltage = tension du condensateur v_C
uncertainty-settling-band = bande d'établissement à 5 %
uncertainty-axis-draws = tirages
uncertainty-series-bins = tirages par classe ({ $bins } classes)
uncertainty-no-finite-values = aucune valeur finie
uncertainty-spec-limit = limite de spécification
uncertainty-percentiles = 5ᵉ / 95ᵉ centile
uncertainty-title = Analyse des tolérances
uncertainty-summary = Les composants réels n'ont pas exactement leur valeur nominale. Choisissez le système : le quart de véhicule (masse suspendue m, ressort k et amortisseur réglé pour ζ à la masse nominale ; la masse varie de ±dm selon la charge du véhicule) ou le circuit RLC série (R, L et C chacun à ±dR, ±dL, ±dC près). Seuls les curseurs du système choisi sont utilisés ; l'autre groupe est ignoré. Les intervalles exacts de ζ, ωₙ et Q sont obtenus aux coins de la boîte de tolérances. Le calcul de Monte-Carlo tire N conceptions (avec une graine : la même graine donne le même résultat), uniformes dans la tolérance ou normales avec la tolérance comme 3σ. Le rendement est la part des tirages dont ζ est dans la fenêtre de spécification et dont le temps d'établissement à 5 % (lâcher depuis le repos) ne dépasse pas la limite.
uncertainty-param-system = système
uncertainty-param-system-suspension = suspension de quart de véhicule
uncertainty-param-system-rlc = RLC série
uncertainty-param-m = suspension : masse suspendue
uncertainty-param-k = suspension : raideur du ressort
uncertainty-param-zeta = suspension : ζ de conception à la masse nominale
uncertainty-param-dm = suspension : tolérance sur la masse ±
uncertainty-param-R = RLC : résistance
uncertainty-param-L = RLC : inductance
uncertainty-param-C = RLC : capacité
uncertainty-param-dR = RLC : tolérance de la résistance ±
uncertainty-param-dL = RLC : tolérance de la bobine ±
uncertainty-param-dC = RLC : tolérance du condensateur ±
uncertainty-param-dist = distribution des composants
uncertainty-param-dist-uniform = uniforme dans ±tolérance
uncertainty-param-dist-normal = normale, tolérance = 3σ
uncertainty-param-N = tirages de Monte-Carlo
uncertainty-param-seed = graine aléatoire
uncertainty-param-zeta-lo = spécification : ζ minimal
uncertainty-param-zeta-hi = spécification : ζ maximal
uncertainty-param-ts-max = spécification : temps d'établissement maximal
uncertainty-param-hist = second histogramme
uncertainty-param-hist-zeta = taux d'amortissement ζ
uncertainty-param-hist-f0 = fréquence propre f0
uncertainty-param-hist-q = facteur de qualité Q
uncertainty-param-hist-bandwidth = bande passante
uncertainty-param-hist-settling-time = temps d'établissement
uncertainty-readout-zeta-min = ζ, minimum (exact)
uncertainty-readout-zeta-max = ζ, maximum (exact)
uncertainty-readout-wn-min = ωₙ, minimum (exact)
uncertainty-readout-wn-max = ωₙ, maximum (exact)
uncertainty-readout-Q-min = Q, minimum (exact)
uncertainty-readout-Q-max = Q, maximum (exact)
uncertainty-readout-yield = rendement (conforme à la spécification)
uncertainty-readout-zeta-p5 = ζ, 5ᵉ centile
uncertainty-readout-zeta-p95 = ζ, 95ᵉ centile
uncertainty-readout-Q-p5 = Q, 5ᵉ centile
uncertainty-readout-Q-p95 = Q, 95ᵉ centile
uncertainty-readout-draws = tirages
uncertainty-readout-compute-time = temps de calcul de Monte-Carlo
uncertainty-plot-band = Faisceau de réponses libres sur la tolérance
uncertainty-plot-zeta-hist = Monte-Carlo : taux d'amortissement ζ
uncertainty-plot-hist = Monte-Carlo : grandeur choisie
uncertainty-preset-1 = Conception ζ = 1 avec masse à ±10 %
uncertainty-preset-2 = Conception ζ = 0,7 avec masse à ±10 %
uncertainty-preset-3 = RLC, composants à 5 %
uncertainty-preset-4 = RLC, composants à 20 %
